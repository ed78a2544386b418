// @maa/language-adl: the host language, its services and the extension API (./browser.js), plus
// the checker of model roots on disk, which needs Node.
export * from './browser.js';
export * from './workspace/root-checker.js';
export * from './workspace/model-root.js';
