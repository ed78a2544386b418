// The one model-root rule (see @maa/language-adl's workspace/model-root.ts), for the clients of
// the family (CLI, IDE backend, IDE front end) without the rest of the language services.
export { declaredPackage, MODEL_ROOT_MARKER, resolveModelRoot, type ModelRootOptions } from '@maa/language-adl/model-root';
