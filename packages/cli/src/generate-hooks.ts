// Module resolution hooks of `maa-gen generate` (registered by generate-loader.ts with
// module.register; they run in Node's hooks thread). An import that resolves to the entry module
// of a package the generation bundle holds (dist/generate-bundle) loads the bundle's entry of it
// instead, so generators loaded at run time share the bundle's one copy of generator-core, the
// language packages and Langium. Every other import resolves as usual.
import type { InitializeHook, ResolveHook } from 'node:module';

/** What generate-loader.ts passes: resolved URL of a package's entry -> URL of the bundle's entry. */
export interface RedirectData {
    readonly redirects: Readonly<Record<string, string>>;
}

let redirects = new Map<string, string>();

export const initialize: InitializeHook<RedirectData> = (data) => {
    redirects = new Map(Object.entries(data.redirects));
};

export const resolve: ResolveHook = async (specifier, context, nextResolve) => {
    const resolved = await nextResolve(specifier, context);
    const to = redirects.get(resolved.url);
    return to === undefined ? resolved : { url: to, format: 'module', shortCircuit: true };
};
