/** The format tags of the grading files (docs/lab.md "Grading"). Imports nothing. */

/** An exercise's grading specification in its grading folder (`examples/lab/<ex>/grading/grading.json`). */
export const GRADING_FILE_NAME = 'grading.json';
/** `grading.json`'s `format`. */
export const GRADING_FORMAT = 'maa-grading/1';
/** A grade job (what @maa/grading hands the Python driver `python -m maa_sim.grading run`). */
export const GRADE_JOB_FORMAT = 'maa-grade-job/1';
/** The report of a scenario run (`maa-sim run --report FILE`). */
export const SCENARIO_REPORT_FORMAT = 'maa-scenario-report/1';
/** The state traces of stream tests (`python -m maa_timesync.streamtest --states FILE`). */
export const STREAM_STATES_FORMAT = 'maa-stream-states/1';
