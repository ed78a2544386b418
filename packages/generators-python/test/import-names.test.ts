import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { checkOneBindingPerName, localNameFor } from '../src/behavior/import-names.js';
import { Imports } from '../src/behavior/common.js';
import { PyImports } from '../src/ros2/model/imports.js';
import { generate, maaGen, tempModelRoot } from './maa-gen.js';
import { ensureVenv, packageDir, pythonFiles, type RunResult, ruffConfig, run, venvPython } from './python-env.js';

// One name, one import: a generated module that imported a name from two modules silently used the
// later one (`from a.types import Kind` then `from b.types import Kind`). Model types now yield an
// alias where their name is taken; a run-time name added after a model type took it is refused.
describe('the names imports bind', () => {
    it('a model type whose name another module took is imported under an alias, the same one every time', () => {
        const imports = new Imports();
        expect(imports.use('a.types', 'Kind')).toBe('Kind');
        expect(imports.use('b.types', 'Kind')).toBe('b_types_Kind');
        expect(imports.use('a.types', 'Kind')).toBe('Kind');
        expect(imports.use('b.types', 'Kind')).toBe('b_types_Kind');
        expect(imports.lines()).toEqual(['from a.types import Kind', 'from b.types import Kind as b_types_Kind']);
    });

    it('a model type named like a run-time name gives way to it', () => {
        const imports = new PyImports().add('maa_ros2', 'Relay').add('app_interfaces.msg', '');
        expect(imports.use('app.model.types', 'Relay')).toBe('app_model_types_Relay');
        expect(imports.use('app.model.types', 'Mode')).toBe('Mode');
        expect(imports.lines()).toEqual([
            'import app_interfaces.msg',
            'from app.model.types import Mode',
            'from app.model.types import Relay as app_model_types_Relay',
            'from maa_ros2 import Relay',
        ]);
        // handed to the behavior generators' builder, the alias stays the type's name there
        const target = imports.into(new Imports());
        expect(target.use('app.model.types', 'Relay')).toBe('app_model_types_Relay');
    });

    it('numbers an alias that is taken too', () => {
        const taken = new Map([
            ['x', new Set(['Kind'])],
            ['y', new Set(['Z as b_types_Kind'])],
        ]);
        expect(localNameFor(taken, 'b.types', 'Kind')).toBe('b_types_Kind_2');
    });

    it('wrap long from-imports one name a line: at 140 columns in timesync builds, at 120 in ROS 2 packages', () => {
        const names = ['AlphaReadingValue', 'BetaReadingValue', 'GammaReadingValue', 'DeltaReadingValue', 'EpsilonReadingValue'];
        const line = `from station.model.app.sensor_types import ${[...names].sort().join(', ')}`;
        expect(line.length).toBeGreaterThan(120);
        expect(line.length).toBeLessThanOrEqual(140);
        const timesync = new Imports();
        const ros2 = new Imports(120);
        const node = new PyImports();
        for (const n of names) {
            timesync.add('station.model.app.sensor_types', n);
            ros2.add('station.model.app.sensor_types', n);
            node.add('station.model.app.sensor_types', n);
        }
        expect(timesync.lines()).toEqual([line]);
        const wrapped = ['from station.model.app.sensor_types import (', ...names.sort().map((n) => `    ${n},`), ')'];
        expect(ros2.lines()).toEqual(wrapped);
        expect(node.lines()).toEqual(wrapped);
    });

    it('refuses a run-time name added after a model type took it, and a module bound to two things', () => {
        const imports = new Imports();
        imports.use('app.types', 'Mapping');
        imports.add('collections.abc', 'Mapping');
        expect(() => imports.lines()).toThrow(/import the name 'Mapping' twice \(app\.types\.Mapping, collections\.abc\.Mapping\)/);
        expect(() =>
            checkOneBindingPerName(
                new Map([
                    ['a.b', new Set([''])],
                    ['a.c', new Set([''])],
                ]),
            ),
        ).not.toThrow();
        expect(() =>
            checkOneBindingPerName(
                new Map([
                    ['a.b', new Set([''])],
                    ['m', new Set(['a'])],
                ]),
            ),
        ).toThrow(/'a' twice/);
    });
});

const APP = `application Both for app.Both {
  platform timesync {
    timesync.Components;
    timesync.AutomataBehavior;
    timesync.DataTypes;
  }
}
application Gated for app.Gated {
  platform rospython {
    ros2.Components;
    ros2.AutomataBehavior;
    ros2.DataTypes;
  }
}
`;

const root = tempModelRoot('import-names', {
    'a/Types.cd': 'package a;\n\nclassdiagram Types {\n  enum Kind { ON, OFF; }\n}\n',
    'b/Types.cd': 'package b;\n\nclassdiagram Types {\n  enum Kind { OFF, ON; }\n}\n',
    // both enums in one component: ports, parameters defaults and guards over each
    'app/Both.arc': `package app;

component Both {
  port in a.Types.Kind x;
  port in b.Types.Kind y;
  port out boolean same;

  <<sync>> compute {
    same = x == a.Types.Kind.ON && y == b.Types.Kind.ON;
  }
}
`,
    // model types named like maa_ros2's Relay (read by a mode guard) and ModeGate (a gated node's port)
    'app/Names.cd': 'package app;\n\nclassdiagram Names {\n  enum Relay { OPEN, CLOSED; }\n  class ModeGate {\n    int v;\n  }\n}\n',
    'app/Pass.arc': `package app;

import app.Names.*;

component Pass {
  port in ModeGate i;
  port out ModeGate o;

  <<sync>> compute {
    if (i != null) {
      o = i;
    }
  }
}
`,
    'app/Gated.arc': `package app;

import app.Names.*;

component Gated {
  port in Relay r;
  port in ModeGate g;
  port out ModeGate o;

  <<sync>> mode automaton {
    initial mode Open {
      Pass p;
      g -> p.i;
      p.o -> o;
    }
    mode Closed {
    }
    Open -> Closed [r == Relay.CLOSED];
    Closed -> Open [r == Relay.OPEN];
  }
}
`,
    // five port types whose one import line is 136 columns in the ROS 2 package (wrapped there at 120)
    'app/Readings.cd': `package app;

classdiagram Readings {
  class TemperatureValue { int v; }
  class HumidityReading { int v; }
  class PressureReading { int v; }
  class LuminosityValue { int v; }
  class WindSpeedReading { int v; }
}
`,
    'app/WeatherStationHub.arc': `package app;

import app.Readings.*;

component WeatherStationHub {
  port in TemperatureValue t;
  port in HumidityReading h;
  port in PressureReading p;
  port in LuminosityValue l;
  port in WindSpeedReading w;
  port out TemperatureValue t2;
  port out HumidityReading h2;
  port out PressureReading p2;
  port out LuminosityValue l2;
  port out WindSpeedReading w2;

  <<sync>> compute {
    t2 = t;
    h2 = h;
    p2 = p;
    l2 = l;
    w2 = w;
  }
}
`,
    'Hub.arcapp': `application Hub for app.WeatherStationHub {
  platform rospython {
    ros2.Components;
    ros2.AutomataBehavior;
    ros2.DataTypes;
  }
  platform timesync {
    timesync.Components;
    timesync.AutomataBehavior;
    timesync.DataTypes;
  }
}
`,
    'Both.arcapp': APP.split('application Gated')[0]!,
    'Gated.arcapp': `application Gated${APP.split('application Gated')[1]!}`,
});

// Both fed one slice: a's ON on x and b's ON on y (whose ordinals differ) make `same` true only if
// each guard compares with its own enum.
const DRIVER = `import json, sys
sys.path.insert(0, sys.argv[1])
import a.types, b.types
from app.both import Both
from maa_timesync import TICK, System
system = System(Both)
system.init()
for port, item in [("x", a.types.Kind.ON), ("x", TICK), ("y", b.types.Kind.ON), ("y", TICK), ("x", a.types.Kind.OFF), ("x", TICK), ("y", b.types.Kind.ON), ("y", TICK)]:
    system.receive(port, item)
system.run()
print(json.dumps(["Tk" if v is TICK else v for v in system.outputs["same"]]))
`;

describe('a component with two types of one name (python-timesync)', () => {
    it('imports the second under an alias, and its guards compare with the right one', async () => {
        await ensureVenv();
        const gen = await generate(path.join(root.dir, 'Both.arcapp'), 'timesync', path.join(root.dir, 'out'), root.dir);
        expect(gen.status, gen.stdout + gen.stderr).toBe(0);
        const build = path.join(root.dir, 'out', 'timesync');
        const both = readFileSync(path.join(build, 'app', 'both.py'), 'utf8');
        expect(both).toContain('from a.types import Kind\nfrom b.types import Kind as b_types_Kind\n');
        expect(both).toContain('((self.x == Kind.ON) and (self.y == b_types_Kind.ON))');
        // maa_app.py's ENUMS keys the two by their qualified names (one simple-name key would drop one)
        const app = readFileSync(path.join(build, 'maa_app.py'), 'utf8');
        expect(app).toContain('"a.Types.Kind": Kind,');
        expect(app).toContain('"b.Types.Kind": b_types_Kind,');
        const ruff = await run(
            venvPython,
            ['-m', 'ruff', 'check', '--config', ruffConfig, '--no-cache', '--output-format', 'concise', 'app', 'a', 'b', 'maa_app.py'],
            build,
        );
        expect(ruff.status, ruff.stdout + ruff.stderr).toBe(0);
        writeFileSync(path.join(root.dir, 'driver.py'), DRIVER);
        const r = await run(venvPython, [path.join(root.dir, 'driver.py'), build], root.dir);
        expect(r.status, r.stderr).toBe(0);
        expect(JSON.parse(r.stdout)).toEqual([true, 'Tk', false, 'Tk']);
    }, 180_000);
});

describe('model types named like run-time names (ROS 2)', () => {
    it('are imported under an alias in the node files and the mode manager, which stay ruff-clean', async () => {
        await ensureVenv();
        const gen = await generate(path.join(root.dir, 'Gated.arcapp'), 'rospython', path.join(root.dir, 'ros'), root.dir);
        expect(gen.status, gen.stdout + gen.stderr).toBe(0);
        const platform = path.join(root.dir, 'ros', 'rospython');
        const nodes = path.join(platform, 'gated', 'gated', 'nodes');
        const manager = readFileSync(path.join(nodes, 'maa_modes.py'), 'utf8');
        expect(manager).toContain('from gated.model.app.names import Relay as gated_model_app_names_Relay\n');
        expect(manager).toContain('from maa_ros2 import InPort, ModeManagerNode, Relay,');
        expect(manager).toContain('enum_port(gated_interfaces.msg.Relay, gated_model_app_names_Relay)');
        expect(manager).toContain('inputs.get("r") == gated_model_app_names_Relay.CLOSED');
        const node = readFileSync(path.join(nodes, 'p.py'), 'utf8');
        expect(node).toContain('from gated.model.app.names import ModeGate as gated_model_app_names_ModeGate\n');
        expect(node).toContain('class_port(gated_interfaces.msg.ModeGate, gated_model_app_names_ModeGate)');
        expect(node).toContain('ModeGate(');
        const ruff = await ruffRos2(platform, 'gated');
        expect(ruff.status, ruff.stdout + ruff.stderr).toBe(0);
        expect(pythonFiles(platform).length).toBeGreaterThan(10);
    }, 180_000);
});

/** `ruff check` of a generated ROS 2 platform folder with the settings of test/ros2 (as the golden test runs it). */
function ruffRos2(platform: string, pkg: string): Promise<RunResult> {
    const known = [pkg, `${pkg}_interfaces`, 'maa_behavior', 'maa_ros2'].map((x) => `'${x}'`).join(',');
    const config = path.join(packageDir, 'test', 'ros2', 'ruff-generated.toml');
    const args = [
        'check',
        '--no-cache',
        '--output-format',
        'concise',
        '--config',
        config,
        '--config',
        `lint.isort.known-third-party=[${known}]`,
    ];
    return run(venvPython, ['-m', 'ruff', ...args, '--extend-exclude', 'maa_behavior', '.'], platform);
}

describe('long import lines', () => {
    it('wrap at 120 columns in the node and behavior files of a ROS 2 package, at 140 in timesync builds', async () => {
        await ensureVenv();
        const gen = await run(
            process.execPath,
            [maaGen, 'generate', path.join(root.dir, 'Hub.arcapp'), '--out', path.join(root.dir, 'hub')],
            root.dir,
        );
        expect(gen.status, gen.stdout + gen.stderr).toBe(0);
        const pkg = path.join(root.dir, 'hub', 'rospython', 'weather_station_hub', 'weather_station_hub');
        const wrapped = 'from weather_station_hub.model.app.readings import (\n    HumidityReading,\n    LuminosityValue,\n';
        expect(readFileSync(path.join(pkg, 'nodes', 'weather_station_hub.py'), 'utf8')).toContain(wrapped);
        expect(readFileSync(path.join(pkg, 'model', 'app', 'weather_station_hub_behavior.py'), 'utf8')).toContain(wrapped);
        const ruff = await ruffRos2(path.join(root.dir, 'hub', 'rospython'), 'weather_station_hub');
        expect(ruff.status, ruff.stdout + ruff.stderr).toBe(0);
        const timesync = readFileSync(path.join(root.dir, 'hub', 'timesync', 'app', 'weather_station_hub.py'), 'utf8');
        expect(timesync).toContain(
            'from app.readings import HumidityReading, LuminosityValue, PressureReading, TemperatureValue, WindSpeedReading\n',
        );
    }, 180_000);
});
