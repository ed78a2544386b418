import { describe, expect, it } from 'vitest';
import { Imports } from '../src/behavior/common.js';
import { PyImports } from '../src/ros2/model/imports.js';

function render(adds: ReadonlyArray<readonly [string, string]>): string[] {
    const imports = new Imports();
    for (const [module, name] of adds) imports.add(module, name);
    return imports.lines();
}

describe("the behavior generators' Imports", () => {
    it("renders the name '' as `import module`, before the from-imports of its section (isort's order)", () => {
        expect(
            render([
                ['std_msgs.msg', 'Int32'],
                ['app_interfaces.msg', ''],
                ['collections.abc', 'Mapping'],
                ['maa_ros2', 'InPort'],
                ['json', ''],
            ]),
        ).toEqual([
            'import json',
            'from collections.abc import Mapping',
            '',
            'import app_interfaces.msg',
            'from maa_ros2 import InPort',
            'from std_msgs.msg import Int32',
        ]);
    });

    it('imports a module and names from it on two lines, never `from m import , X`', () => {
        expect(
            render([
                ['app_interfaces.msg', 'Gear'],
                ['app_interfaces.msg', ''],
            ]),
        ).toEqual(['import app_interfaces.msg', 'from app_interfaces.msg import Gear']);
    });

    it("takes a mode manager's PyImports with a message module (the mode-types fixture's case)", () => {
        const node = new PyImports().add('gear_router_interfaces.msg', '').add('gear_router.model.route.signals', 'Gear');
        node.addAll('maa_ros2', ['InPort', 'enum_port']);
        const imports = new Imports();
        imports.add('collections.abc', 'Mapping');
        expect(node.into(imports).lines()).toEqual([
            'from collections.abc import Mapping',
            '',
            'import gear_router_interfaces.msg',
            'from gear_router.model.route.signals import Gear',
            'from maa_ros2 import InPort, enum_port',
        ]);
    });

    it('lists a name added twice once', () => {
        expect(
            render([
                ['maa_ros2', 'Relay'],
                ['maa_ros2', 'Relay'],
                ['x', ''],
                ['x', ''],
            ]),
        ).toEqual(['import x', 'from maa_ros2 import Relay']);
    });

    it('renders nothing for no imports and keeps aliases on lines of their own', () => {
        expect(render([])).toEqual([]);
        expect(
            render([
                ['app.a', 'A as AA'],
                ['app.a', 'B'],
            ]),
        ).toEqual(['from app.a import A as AA', 'from app.a import B']);
    });
});
