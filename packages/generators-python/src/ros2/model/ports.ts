import { GenerationError } from '@maa/generator-core/node';
import type { PortView } from '@maa/generator-core';
import { primitiveOf, typeKey, type RosDataTypeResult } from '../naming.js';
import type { PyImports } from './imports.js';
import type { PortCodec } from './model.js';

/**
 * How a port's values travel on its topic: primitives as std_msgs (a char as a one-character
 * string), enums and non-generic classes as the messages of ros2.DataTypes. Adds the imports the
 * codec needs.
 */
export function portCodec(p: PortView, dt: RosDataTypeResult, imports: PyImports): PortCodec {
    const prim = primitiveOf(p.type);
    if (prim) {
        imports.add('std_msgs.msg', prim.std);
        // A char is its code inside the behavior and a one-character string on the topic.
        const isChar = p.typeName === 'char' || p.typeName === 'Character';
        const helper = isChar ? 'char_port' : 'std_port';
        return {
            rosType: `std_msgs/msg/${prim.std}`,
            helper,
            codec: isChar ? `${helper}(${prim.std})` : `${helper}(${prim.std}, ${prim.py})`,
            sampled: true,
        };
    }
    if (p.type.kind === 'object') {
        const msg = dt.messages[typeKey(p.type)];
        const py = dt.types?.[typeKey({ kind: 'object', decl: p.type.decl, args: [] })];
        if (msg && py?.module && py.name) {
            const local = imports.add(msg.module, '').use(py.module, py.name);
            const qualified = `${msg.module}.${msg.name}`;
            const helper = msg.kind === 'enum' ? 'enum_port' : 'class_port';
            return { rosType: msg.type, helper, codec: `${helper}(${qualified}, ${local})`, sampled: false };
        }
    }
    throw new GenerationError(
        `ros2.Components cannot carry port '${p.name}' of type ${p.typeName} on a ROS 2 topic (primitives, enums and non-generic classes can)`,
        p.node,
    );
}

/** The `maa_ros2` names the codecs of some ports use (`std_port`, `enum_port`). */
export function codecNames(ports: Iterable<PortCodec>): string[] {
    return [...new Set([...ports].map((p) => p.helper))];
}
