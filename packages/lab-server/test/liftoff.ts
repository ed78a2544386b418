// Imported (for its effect) by every test file that opens a PGlite store: V8 compiles PGlite's
// WebAssembly PostgreSQL with its baseline compiler (Liftoff) only. By default V8 also optimizes
// its hot functions with TurboFan in background threads, which costs up to 6 s of CPU per
// process, more than a test file's queries ever win back (docs/testing.md, "Where the time
// goes"). The flag is read when a module is compiled, so setting it before the first PGlite
// starts suffices. PGlite still runs PostgreSQL as in production, only less optimized; the lab
// server itself keeps V8's defaults.
import v8 from 'node:v8';

/** For the child processes a test starts that open a PGlite store: `node ${LIFTOFF_ONLY} ...`. */
export const LIFTOFF_ONLY = '--liftoff-only';

v8.setFlagsFromString(LIFTOFF_ONLY);
