/**
 * `maa_app.py`, the application module of a python-timesync build: the root type, the component
 * types and enums by name (stream tests), and the simulator's lock-step factory with the port
 * topics and node names it publishes under.
 */
import type { ArchitectureModel, ComponentGenerationContext, PortView } from '@maa/generator-core';
import { automatonEntry } from '../behavior/automata-table.js';
import { Imports, typeRef } from '../behavior/common.js';
import { pyName } from '../python/expressions.js';
import { renderPython } from '../python/templates.js';
import { primitiveOf, rosName } from '../ros2/naming.js';
import { componentModule } from './component-module.js';
import type { AppModuleView } from './views.js';

/** The application module's name: `lockstep.json`'s factory lives in it. */
export const APP_MODULE = 'maa_app';

export function writeAppModule(ctx: ComponentGenerationContext): void {
    const { architecture } = ctx;
    const root = architecture.root;
    const imports = new Imports();
    imports.add('maa_timesync.lockstep', 'LockstepApp');
    imports.add('maa_timesync', 'ComponentType');
    imports.add('enum', 'Enum');
    imports.add('collections.abc', 'Mapping');
    const components = componentsByName(architecture, imports);
    const enumTypes = architecture.dataTypes.filter((t) => t.kind === 'enum');
    const shared = sharedNames(enumTypes.map((t) => t.name));
    // Stream tests name an enum by its simple name; two enums of one simple name are keyed by
    // their qualified names instead (a repeated dictionary key would silently drop one).
    const enums = enumTypes.map((t) => ({
        name: shared.has(t.name) ? t.qualifiedName : t.name,
        type: typeRef(ctx.datatypes, imports, t.node),
    }));
    ctx.out.file(`${APP_MODULE}.py`).write(
        renderPython('timesync/app.py.njk', {
            application: ctx.platform.application,
            rootQualifiedName: root.qualifiedName,
            imports: imports.lines(),
            rootAlias: moduleAlias(componentModule(root).module),
            components,
            enums,
            ...liveTopics(architecture),
        }),
        root.node,
    );
}

/** The names that occur more than once. */
function sharedNames(names: readonly string[]): Set<string> {
    const seen = new Set<string>();
    return new Set(names.filter((n) => seen.has(n) || !seen.add(n)));
}

/** A component module's import alias in the app module (`_pkg_module`): unique where class names are not. */
function moduleAlias(module: string): string {
    return `_${module.replace(/\./g, '_')}`;
}

/** Every component type by qualified name (`COMPONENTS`), each imported under its module's alias. */
function componentsByName(architecture: ArchitectureModel, imports: Imports): AppModuleView['components'] {
    return architecture.components.map((c) => {
        const m = componentModule(c);
        const alias = moduleAlias(m.module);
        imports.add(m.module, `${pyName(c.name)} as ${alias}`);
        return { name: c.qualifiedName, alias };
    });
}

/**
 * Live values in the simulator's lock-step mode: every port value under its ROS 2 topic name (the
 * ros2 generator's rule), so the IDE sees the same topics in both modes: the root's in ports and
 * the out ports of atomic instances. Mode components have a live state too, their mode, under
 * their instance's node path as on ROS 2. The automata table (`AUTOMATA`) lists the automaton
 * instances with their states and transitions for the IDE.
 */
function liveTopics(architecture: ArchitectureModel): Pick<AppModuleView, 'portTopics' | 'nodeNames' | 'automata'> {
    const rootNs = `/${rosName(architecture.root.name)}`;
    const portTopics: AppModuleView['portTopics'][number][] = [];
    const nodeNames: AppModuleView['nodeNames'][number][] = [];
    const automata: AppModuleView['automata'][number][] = [];
    for (const p of architecture.root.ports.filter((x) => x.direction === 'in')) {
        portTopics.push({ key: p.name, topic: `${rootNs}/${rosName(p.name)}`, type: topicType(p) });
    }
    for (const inst of architecture.instances.filter((i) => i.component.atomic || i.component.modes)) {
        const node = [rootNs, ...inst.path.map(rosName)].join('/');
        nodeNames.push({ path: inst.path.join('.'), node });
        const automaton = automatonEntry(inst, node);
        if (automaton) automata.push({ path: automaton.instancePath, json: JSON.stringify(automaton) });
        if (!inst.component.atomic) continue;
        for (const p of inst.component.ports.filter((x) => x.direction === 'out')) {
            portTopics.push({ key: `${inst.path.join('.')}.${p.name}`, topic: `${node}/${rosName(p.name)}`, type: topicType(p) });
        }
    }
    return { portTopics, nodeNames, automata };
}

/** Primitives travel as their std_msgs type; enums as their constant name and classes as JSON, both in std_msgs/String. */
function topicType(p: PortView): string {
    return `std_msgs/msg/${primitiveOf(p.type)?.std ?? 'String'}`;
}
