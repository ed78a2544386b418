// @maa/generators-python: the Python generator families. The generators are loaded through the
// manifests in package.json (`maa.generators`); this module exports helpers for tests and tools.
export { default as timesyncComponents, componentModule } from './timesync/components.js';
export { default as timesyncDataTypes, diagramModule } from './timesync/datatypes.js';
export { default as automataBehavior, automatonClass, behaviorModule, translatableRule } from './behavior/automata.js';
export { default as robotArmBehavior, robotArmRule } from './behavior/robotarm.js';
export { computeClass } from './behavior/compute.js';
export * from './behavior/common.js';
export * from './python/expressions.js';
export { findStreamFiles, selectCases as selectStreamCases, type StreamTestResult } from './timesync/stream-tests.js';
