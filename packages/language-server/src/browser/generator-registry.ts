import { GeneratorRegistry } from '@maa/generator-core';
import { BUNDLED_GENERATORS } from '../generated/generator-manifests.js';

/**
 * The generators `.arcapp` files resolve against in a browser, where no installed packages can
 * be discovered: the manifests of the packages installed when this package was built.
 */
export function bundledGeneratorRegistry(): GeneratorRegistry {
    return new GeneratorRegistry(BUNDLED_GENERATORS);
}
