// The `prepack` of every public package: copies the repository's LICENSE into the package folder,
// because npm puts a package's own LICENSE file into its tarball, never the repository's (the
// copies are ignored by git; one text, at the root).
import { copyFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
copyFileSync(path.join(repo, 'LICENSE'), path.join(process.cwd(), 'LICENSE'));
