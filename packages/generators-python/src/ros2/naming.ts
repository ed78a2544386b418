import { GenerationError } from '@maa/generator-core/node';
import { AstUtils, type AstNode } from 'langium';
import type { SymType } from '@maa/language-adl';
import { rosName } from './ros-names.js';
import { dataTypeQualifiedName, pascalCase, type DataTypeResult, type PlatformInfo } from '@maa/generator-core';

/**
 * Names and type mappings shared by the ros2-python generators (ros2.Components, ros2.DataTypes):
 * the ROS package names of an application, and how model types travel as ROS 2 messages.
 */

/** The ament_python package of an application: the root component's name in snake_case. */
export function rosPackageName(platform: PlatformInfo): string {
    const simple = platform.rootComponent.split('.').pop() ?? platform.rootComponent;
    return rosName(simple);
}

/** The sibling ament_cmake interface package. */
export function interfacePackageName(platform: PlatformInfo): string {
    return `${rosPackageName(platform)}_interfaces`;
}

export { rosName } from './ros-names.js';

/** A message field name: rosidl wants lower snake_case without double or trailing underscores. */
export function fieldName(name: string): string {
    return rosName(name).replace(/_+/g, '_').replace(/_$/, '');
}

/** A message type name: rosidl wants PascalCase of letters and digits. */
export function messageName(name: string): string {
    const p = pascalCase(name).replace(/[^A-Za-z0-9]/g, '');
    return /^[A-Z]/.test(p) ? p : `M${p}`;
}

/** A message constant name: rosidl wants UPPER_CASE. */
export function constantName(name: string): string {
    return name.toUpperCase().replace(/[^A-Z0-9_]/g, '_');
}

export function isBuiltinDecl(node: AstNode): boolean {
    return AstUtils.getDocument(node).uri.scheme === 'builtin';
}

/** Model primitives (and their boxed forms) -> rosidl field type and std_msgs message. */
const PRIMITIVES: Readonly<Record<string, { field: string; std: string; py: string }>> = {
    boolean: { field: 'bool', std: 'Bool', py: 'bool' },
    Boolean: { field: 'bool', std: 'Bool', py: 'bool' },
    byte: { field: 'int8', std: 'Int8', py: 'int' },
    Byte: { field: 'int8', std: 'Int8', py: 'int' },
    short: { field: 'int16', std: 'Int16', py: 'int' },
    Short: { field: 'int16', std: 'Int16', py: 'int' },
    int: { field: 'int32', std: 'Int32', py: 'int' },
    Integer: { field: 'int32', std: 'Int32', py: 'int' },
    long: { field: 'int64', std: 'Int64', py: 'int' },
    Long: { field: 'int64', std: 'Int64', py: 'int' },
    float: { field: 'float32', std: 'Float32', py: 'float' },
    Float: { field: 'float32', std: 'Float32', py: 'float' },
    double: { field: 'float64', std: 'Float64', py: 'float' },
    Double: { field: 'float64', std: 'Float64', py: 'float' },
    char: { field: 'string', std: 'String', py: 'str' },
    Character: { field: 'string', std: 'String', py: 'str' },
    String: { field: 'string', std: 'String', py: 'str' },
};

/** The primitive mapping of a type (primitive or boxed), if it is one. */
export function primitiveOf(t: SymType): { field: string; std: string; py: string } | undefined {
    if (t.kind === 'primitive') return PRIMITIVES[t.name];
    if (t.kind === 'object' && t.args.length === 0 && isBuiltinDecl(t.decl)) return PRIMITIVES[t.decl.name];
    return undefined;
}

/** The message name of a class-diagram type use; generic uses get one message per instantiation (`Pair<int, Color>` -> `PairIntColor`). */
export function messageNameOf(t: SymType, where: AstNode): string {
    if (t.kind !== 'object' || isBuiltinDecl(t.decl)) {
        throw new GenerationError(`type ${describe(t)} has no message of its own`, where);
    }
    return messageName(t.decl.name) + t.args.map((a) => typeToken(a, where)).join('');
}

function typeToken(t: SymType, where: AstNode): string {
    const prim = primitiveOf(t);
    if (prim) return prim.std;
    if (t.kind === 'array') return `${typeToken(t.component, where)}Array`;
    if (t.kind === 'object') return messageNameOf(t, where);
    throw new GenerationError(`type ${describe(t)} cannot be translated to a ROS 2 message`, where);
}

export function describe(t: SymType): string {
    switch (t.kind) {
        case 'primitive':
            return t.name;
        case 'object':
            return t.args.length ? `${t.decl.name}<${t.args.map(describe).join(', ')}>` : t.decl.name;
        case 'array':
            return `${describe(t.component)}[]`;
        case 'typevar':
            return t.decl.name;
        default:
            return t.kind;
    }
}

/** Keys of the messages in the data type result: the qualified model type (`toast.types.Types.Pair<int, double>`). */
export function typeKey(t: SymType): string {
    if (t.kind === 'object') {
        const name = isBuiltinDecl(t.decl) ? t.decl.name : dataTypeQualifiedName(t.decl);
        return t.args.length ? `${name}<${t.args.map(typeKey).join(', ')}>` : name;
    }
    if (t.kind === 'array') return `${typeKey(t.component)}[]`;
    if (t.kind === 'primitive') return t.name;
    return t.kind;
}

/** What ros2.DataTypes tells ros2.Components about one message. */
export interface RosMessage {
    /** `toast_service_robot_interfaces/msg/ToastColor` */
    readonly type: string;
    /** Python module and class: `toast_service_robot_interfaces.msg`, `ToastColor` */
    readonly module: string;
    readonly name: string;
    readonly kind: 'enum' | 'class';
}

export interface RosDataTypeResult extends DataTypeResult {
    readonly interfacePackage: string;
    /** By type key (see typeKey). */
    readonly messages: Readonly<Record<string, RosMessage>>;
}

export function isRosDataTypeResult(d: DataTypeResult): d is RosDataTypeResult {
    return (
        typeof (d as { interfacePackage?: unknown }).interfacePackage === 'string' &&
        typeof (d as { messages?: unknown }).messages === 'object'
    );
}

/** The subpackage of the ament_python package that holds the Python data types and behavior classes. */
export const MODEL_PACKAGE = 'model';
