import { contract } from '../contract.js';
import { AutomatonEntry, TopicMapAnswer } from './schema.js';

export * from './schema.js';

/** `GET /api/sim/topics?app=&platform=`. */
export const topicMapContract = contract('GET /api/sim/topics answer', TopicMapAnswer);
/** One entry of a generated automata table (the timesync app module's `AUTOMATA`). */
export const automatonEntryContract = contract('automata table entry', AutomatonEntry);
