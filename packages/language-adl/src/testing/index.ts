// Test support for the language packages (`@maa/language-adl/testing`); imports Vitest.
export * from './model-validation.js';
export * from './catalog-tests.js';
export * from './fuzz-corpus.js';
export * from './montiarc-cocos.js';
