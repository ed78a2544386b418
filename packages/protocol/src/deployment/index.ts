import { contract } from '../contract.js';
import { Deployment } from './schema.js';

export * from './schema.js';

/** The name of the file in a generated ROS 2 package folder. */
export { DEPLOYMENT_FILE_NAME } from '../formats.js';

/** Checks a parsed `deployment.json` (the per-file rules: unique node names etc. are the reader's). */
export const deploymentContract = contract('deployment', Deployment);
