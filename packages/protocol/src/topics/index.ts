import { contract } from '../contract.js';
import { TopicMapAnswer } from './schema.js';

export * from './schema.js';

/** `GET /api/sim/topics?app=&platform=`. */
export const topicMapContract = contract('GET /api/sim/topics answer', TopicMapAnswer);
