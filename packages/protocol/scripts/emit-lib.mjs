/**
 * The artifacts emitted from the contracts (built dist/): JSON Schema files in schema/ and the
 * Python module of sim-server (the schemas and TypedDicts of the formats maa-sim reads).
 * `npm run emit -w packages/protocol` (emit.mjs, after the build) writes them; the build itself
 * does not, so that test/emitted.test.ts, which regenerates them, fails when a committed copy is
 * stale.
 */
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import * as protocol from '../dist/index.js';

export const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const repoDir = path.resolve(packageDir, '../..');

/** The contracts emitted as JSON Schema files, by file stem. */
export const SCHEMA_FILES = {
    'trace-file': protocol.TraceFile,
    deployment: protocol.Deployment,
    exercise: protocol.ExerciseManifest,
    'released-exercise': protocol.ReleasedExercise,
    'topic-map': protocol.TopicMapAnswer,
    lockstep: protocol.Lockstep,
    'step-outputs': protocol.StepOutputs,
    'simulator-status': protocol.SimulatorStatus,
    'simulator-progress': protocol.SimulatorProgress,
    'simulator-finished': protocol.SimulatorFinished,
    grading: protocol.GradingSpec,
    'submission-grade': protocol.SubmissionGrade,
    'grade-job': protocol.GradeJob,
    'grade-driver-line': protocol.DriverLine,
    'scenario-report': protocol.ScenarioReport,
    'stream-states': protocol.StreamStates,
    'transition-event': protocol.TransitionEvent,
    'program-step-event': protocol.ProgramStepEvent,
    'set-breakpoints': protocol.SetBreakpoints,
};

/** The contracts maa-sim reads, by Python constant prefix. */
const PYTHON_SCHEMAS = {
    DEPLOYMENT: protocol.Deployment,
    LOCKSTEP: protocol.Lockstep,
    STEP_OUTPUTS: protocol.StepOutputs,
    SIMULATOR_STATUS: protocol.SimulatorStatus,
    SIMULATOR_PROGRESS: protocol.SimulatorProgress,
    SIMULATOR_FINISHED: protocol.SimulatorFinished,
    GRADING_SPEC: protocol.GradingSpec,
    SUBMISSION_GRADE: protocol.SubmissionGrade,
    GRADE_JOB: protocol.GradeJob,
    GRADE_DRIVER_LINE: protocol.DriverLine,
    SCENARIO_REPORT: protocol.ScenarioReport,
    STREAM_STATES: protocol.StreamStates,
    SET_BREAKPOINTS: protocol.SetBreakpoints,
};

/** A schema as plain JSON (TypeBox's symbol keys dropped). */
function plain(schema) {
    return JSON.parse(JSON.stringify(schema));
}

function schemaFile(schema) {
    return `${JSON.stringify({ $schema: 'https://json-schema.org/draft/2020-12/schema', ...plain(schema) }, null, 2)}\n`;
}

// ---- Python TypedDicts from JSON Schema (the subset the contracts use) ----

const pascal = (s) => s.replace(/(^|[_\-\s])([a-z0-9])/gi, (_m, _p, c) => c.toUpperCase());

class PythonTypes {
    classes = [];
    named = new Set();

    type(s, hint) {
        if (s.const !== undefined) return `Literal[${JSON.stringify(s.const)}]`;
        if (s.anyOf) return [...new Set(s.anyOf.filter((x) => !isNever(x)).map((x, i) => this.type(x, `${hint}${i}`)))].join(' | ');
        if (s.allOf) {
            const record = s.allOf.find((x) => x.patternProperties);
            if (record) return this.type(record, hint);
            return this.type(
                s.allOf.find((x) => x.properties),
                hint,
            );
        }
        if (s.type === 'object' && s.patternProperties)
            return `dict[str, ${this.type(Object.values(s.patternProperties)[0], `${hint}Value`)}]`;
        if (s.type === 'object') return this.typedDict(s, s.title ?? hint);
        if (s.type === 'array') return `list[${this.type(s.items, `${hint}Item`)}]`;
        return { string: 'str', number: 'float', integer: 'int', boolean: 'bool', null: 'None' }[s.type] ?? 'Any';
    }

    typedDict(s, name) {
        if (this.named.has(name)) return name;
        this.named.add(name);
        const required = new Set(s.required ?? []);
        const fields = [];
        for (const [key, value] of Object.entries(s.properties ?? {})) {
            if (isNever(value)) continue;
            const t = this.type(value, `${name}${pascal(key)}`);
            fields.push(field(key, required.has(key) ? t : `NotRequired[${t}]`));
        }
        const doc = s.description ? `    """${s.description}"""\n\n` : '';
        const keys = Object.entries(s.properties ?? {})
            .filter(([, v]) => !isNever(v))
            .map(([k]) => k);
        if (keys.some((k) => PYTHON_KEYWORDS.has(k))) {
            // a key that is a Python keyword (`from`) cannot be a class attribute: the functional syntax
            const items = keys.map((k, i) => `    ${JSON.stringify(k)}: ${fields[i].replace(/^ {4}[^:]+: /, '')},`);
            this.classes.push(`${name} = TypedDict(\n    "${name}",\n    {\n${items.map((l) => `    ${l}`).join('\n')}\n    },\n)\n`);
            return name;
        }
        this.classes.push(`class ${name}(TypedDict):\n${doc}${fields.join('\n') || '    pass'}\n`);
        return name;
    }
}

/** A TypedDict field, wrapped the way `ruff format` wraps it when longer than sim-server's 120 columns. */
function field(key, t) {
    const line = `    ${key}: ${t}`;
    if (line.length <= 120) return line;
    const list = /^list\[(.*)\]$/.exec(t);
    if (list && 8 + list[1].length <= 120) return `    ${key}: list[\n        ${list[1]}\n    ]`;
    return `    ${key}: (\n        ${t.split(' | ').join('\n        | ')}\n    )`;
}

/** Python's keywords: not usable as TypedDict class attributes. */
const PYTHON_KEYWORDS = new Set([
    'False',
    'None',
    'True',
    'and',
    'as',
    'assert',
    'async',
    'await',
    'break',
    'class',
    'continue',
    'def',
    'del',
    'elif',
    'else',
    'except',
    'finally',
    'for',
    'from',
    'global',
    'if',
    'import',
    'in',
    'is',
    'lambda',
    'nonlocal',
    'not',
    'or',
    'pass',
    'raise',
    'return',
    'try',
    'while',
    'with',
    'yield',
]);

const isNever = (s) => s && typeof s === 'object' && s.not && Object.keys(s.not).length === 0;

function pythonModule() {
    const types = new PythonTypes();
    const constants = [];
    for (const [prefix, schema] of Object.entries(PYTHON_SCHEMAS)) {
        types.type(plain(schema), pascal(prefix.toLowerCase()));
        constants.push(
            `${prefix}_SCHEMA: Final[dict[str, Any]] = json.loads(\n    r"""\n${JSON.stringify(plain(schema), null, 1)}\n"""\n)\n`,
        );
    }
    const data = [
        `#: The simulator's platform topics (@maa/protocol SIMULATOR_TOPICS): name, type, publisher, description.\n` +
            `SIMULATOR_TOPICS: Final[list[dict[str, str]]] = json.loads(\n    r"""\n${JSON.stringify(protocol.SIMULATOR_TOPICS, null, 1)}\n"""\n)\n`,
        `AUTOMATON_STATES_TOPIC: Final = ${JSON.stringify(protocol.AUTOMATON_STATES_TOPIC)}\n`,
        `TRANSITIONS_TOPIC: Final = ${JSON.stringify(protocol.TRANSITIONS_TOPIC)}\n`,
        `PROGRAM_STEPS_TOPIC: Final = ${JSON.stringify(protocol.PROGRAM_STEPS_TOPIC)}\n`,
    ];
    return `# Generated by packages/protocol (npm run emit -w packages/protocol, scripts/emit-lib.mjs) from the
# wire contracts of @maa/protocol: do not edit; change the contract in packages/protocol/src, build, emit.
# packages/protocol/test/emitted.test.ts fails when this file differs from what the build emits.
"""The wire contracts maa-sim reads: their JSON Schemas and TypedDicts (docs/extending.md, "Wire contracts")."""

from __future__ import annotations

import json
from typing import Any, Final, Literal, NotRequired, TypedDict

${constants.join('\n')}
${data.join('\n')}

${types.classes.join('\n\n')}`;
}

/** Every emitted artifact: repository-relative path → content. */
export function artifacts() {
    const out = new Map();
    for (const [stem, schema] of Object.entries(SCHEMA_FILES)) out.set(`packages/protocol/schema/${stem}.schema.json`, schemaFile(schema));
    out.set('sim-server/src/maa_sim/protocol.py', pythonModule());
    return out;
}
