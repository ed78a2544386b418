import { GenerationError } from '@maa/generator-core/node';
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import type { ComponentGenerationContext, ComponentGeneratorFactory } from '@maa/generator-core';
import { Imports } from '../behavior/common.js';
import { modeTransitionBody } from '../timesync/modes.js';
import { MODEL_PACKAGE, interfacePackageName, isRosDataTypeResult, rosName, rosPackageName, type RosDataTypeResult } from './naming.js';
import { buildApplication } from './model/build.js';
import { ROS2_LINE_LENGTH } from './model/imports.js';
import { deploymentJson, deploymentOf } from './model/deployment.js';
import type { ComponentNode, ModeManagerNode, Parameter, Ros2Application } from './model/model.js';
import { checkTopicRules } from './model/topic-rules.js';
import { nodeBehaviors, pyTuple, type Emit, type NodeBehaviors } from './node-behaviors.js';

export { importLines } from './model/imports.js';
export { platformTopics } from './node-behaviors.js';

/**
 * ros2.Components: one rclpy node per atomic component instance (the hierarchy flattened; the
 * instance path names the node), every connector chain from a source port to its targets one
 * topic with exactly one publisher, parameters from configuration arguments, an ament_python
 * package (package.xml format 3, setup.py, setup.cfg, resource/<pkg>, console scripts), a
 * launch file (launch_ros) and `deployment.json` for tools without `launch` (the simulator).
 * Behavior classes come from the behavior generators (maa_behavior); `<<handwritten>>`
 * components get a generated base class and a user file created once.
 *
 * The generator builds the typed application model (model/), checks the topic rules on it, and
 * renders it: Python through the templates in `templates/ros2/`, deployment.json by serializing
 * the model.
 *
 * Output (platform folder):
 *   <pkg>/                       the ament_python package (deployment.json at its top)
 *   <pkg>_interfaces/            ros2.DataTypes' ament_cmake package
 */
const create: ComponentGeneratorFactory = ({ packageDir }) => ({
    kind: 'component',
    async generate(ctx) {
        if (!isRosDataTypeResult(ctx.datatypes)) {
            throw new GenerationError(
                'ros2.Components needs the message types of ros2.DataTypes (configure ros2.DataTypes in this platform)',
            );
        }
        const dt = ctx.datatypes;
        const pkg = rosPackageName(ctx.platform);
        const files = new Set<string>();
        const emit: Emit = (file, text, element, userFile = false) => {
            files.add(file);
            ctx.out.file(file, userFile ? { userFile: true } : undefined).write(text, element);
        };
        const behaviors = await nodeBehaviors(ctx, dt, pkg, emit);
        const app = buildApplication({
            arch: ctx.architecture,
            dt,
            pkg,
            ifacePkg: interfacePackageName(ctx.platform),
            behaviors: behaviors.byComponent,
        });
        checkTopicRules(app);
        for (const n of app.nodes) emit(n.file, renderNode(ctx, app, n), n.instance.node ?? n.component.node);
        for (const mg of app.managers) emit(mg.file, renderModeManager(ctx, app, mg, dt), mg.instance.component.modes!.node);
        const pyPackages = writePackageInits(ctx, app, dt, behaviors, files, emit);
        for (const rte of ['maa_behavior', 'maa_ros2']) {
            for (const { file, text } of rteFiles(packageDir, rte)) emit(`${pkg}/${file}`, text);
        }
        writePackageFiles(ctx, app, pyPackages, emit);
        emit(
            `${pkg}/deployment.json`,
            deploymentJson(app, deploymentOf(app, ctx.architecture.root.qualifiedName)),
            ctx.architecture.root.node,
        );
    },
});

export default create;

function compare(a: string, b: string): number {
    return a < b ? -1 : a > b ? 1 : 0;
}

/** Reads the files of an RTE package shipped in `rte/<name>/`. */
function rteFiles(packageDir: string, name: string): Array<{ file: string; text: string }> {
    const dir = path.join(packageDir, 'rte', name);
    return readdirSync(dir)
        .filter((f) => f.endsWith('.py') || f === 'py.typed')
        .sort()
        .map((f) => ({ file: `${name}/${f}`, text: readFileSync(path.join(dir, f), 'utf8') }));
}

/** A parameter's value as a Python literal (a float keeps its decimal point). */
function pyLiteral(p: Parameter): string {
    const v = p.value;
    if (typeof v === 'boolean') return v ? 'True' : 'False';
    if (typeof v === 'number') return p.float && Number.isInteger(v) ? `${v}.0` : String(v);
    return JSON.stringify(v);
}

function parameterViews(n: ComponentNode | ModeManagerNode): { params: object[]; enumParams: Parameter[] } {
    return {
        params: n.parameters.map((p) => ({ name: p.name, literal: pyLiteral(p), enumType: p.enumType })),
        enumParams: n.parameters.filter((p) => p.enumType),
    };
}

function renderNode(ctx: ComponentGenerationContext, app: Ros2Application, n: ComponentNode): string {
    return ctx.templates.render('node.py.njk', {
        n,
        pkg: app.pkg,
        behavior: n.behavior,
        instance: n.instancePath,
        imports: n.imports.lines(),
        ...parameterViews(n),
        gates: n.gates.map((g) => ({ topic: g.topic, initial: g.initial, modes: pyTuple(g.modes) })),
    });
}

function renderModeManager(ctx: ComponentGenerationContext, app: Ros2Application, mg: ModeManagerNode, dt: RosDataTypeResult): string {
    const c = mg.instance.component;
    // the node's imports first, so that the guards' model types take the names (or aliases) they have there
    const imports = mg.imports.into(new Imports(ROS2_LINE_LENGTH));
    const body = modeTransitionBody(c, dt, imports, 'maa_ros2.modes');
    return ctx.templates.render('mode_manager.py.njk', {
        mg,
        pkg: app.pkg,
        instance: mg.instancePath,
        qualifiedName: c.qualifiedName,
        imports: imports.lines(),
        inputLines: mg.inputs.flatMap((p) =>
            tupleItem('InPort', [JSON.stringify(p.port), JSON.stringify(p.topic), p.codec, `sampled=${p.sampled ? 'True' : 'False'}`]),
        ),
        relayLines: mg.relays.flatMap((r) =>
            tupleItem('Relay', [JSON.stringify(r.source), JSON.stringify(r.target), r.codec, pyTuple(r.modes)]),
        ),
        ...parameterViews(mg),
        body: body.map((l) => `    ${l}`),
        initial: c.modes!.initial,
        timing: c.modes!.timing,
    });
}

/**
 * One item of a tuple of calls, `    Call(a, b),`; longer than a line, one argument a line (as the
 * node files write theirs), since topic names and message modules grow with the model's names.
 */
function tupleItem(call: string, args: readonly string[]): string[] {
    const line = `    ${call}(${args.join(', ')}),`;
    return line.length <= ROS2_LINE_LENGTH ? [line] : [`    ${call}(`, ...args.map((a) => `        ${a},`), '    ),'];
}

/** `__init__.py` of every Python package of the ament package (behavior generators wrote their modules); returns the packages. */
function writePackageInits(
    ctx: ComponentGenerationContext,
    app: Ros2Application,
    dt: RosDataTypeResult,
    behaviors: NodeBehaviors,
    files: ReadonlySet<string>,
    emit: Emit,
): string[] {
    const pkg = app.pkg;
    const modelFiles = [...behaviors.modelFiles].map((f) => `${pkg}/${pkg}/${MODEL_PACKAGE}/${f}`);
    const pyFiles = [...files, ...modelFiles];
    const packages = new Set<string>([`${pkg}/${pkg}`, `${pkg}/${pkg}/nodes`, `${pkg}/${pkg}/${MODEL_PACKAGE}`]);
    if (behaviors.handwritten) packages.add(`${pkg}/${pkg}/handwritten`);
    for (const type of Object.values(dt.types ?? {})) {
        if (type.module) pyFiles.push(`${type.module.replace(/\./g, '/')}.py`.replace(new RegExp(`^${pkg}/`), `${pkg}/${pkg}/`));
    }
    for (const f of pyFiles) {
        const parts = f.split('/');
        for (let i = 3; i < parts.length; i++) packages.add(parts.slice(0, i).join('/'));
    }
    const written = new Set(modelFiles);
    const pyPackages = [...packages].filter((p) => p.startsWith(`${pkg}/${pkg}`)).sort(compare);
    for (const p of pyPackages) {
        if (written.has(`${p}/__init__.py`)) continue;
        const doc =
            p === `${pkg}/${pkg}`
                ? `The ROS 2 nodes of application ${ctx.platform.application} (${ctx.architecture.root.qualifiedName}), generated by ros2.Components.`
                : 'Generated package.';
        emit(`${p}/__init__.py`, `"""${doc}"""\n`);
    }
    return pyPackages;
}

/** package.xml, setup.py, setup.cfg, the ament resource marker and the launch file. */
function writePackageFiles(ctx: ComponentGenerationContext, app: Ros2Application, pyPackages: readonly string[], emit: Emit): void {
    const { pkg, ifacePkg } = app;
    const root = ctx.architecture.root;
    const nodes = [...app.nodes, ...app.managers];
    const pythonPackages = [...pyPackages.map((p) => p.slice(pkg.length + 1).replace(/\//g, '.')), 'maa_behavior', 'maa_ros2'].sort(
        compare,
    );
    const scripts = nodes.map((n) => ({ name: n.moduleName, module: n.module }));
    const info = {
        pkg,
        ifacePkg,
        app: ctx.platform.application,
        root: root.qualifiedName,
        launch: `${rosName(ctx.platform.application)}.launch.py`,
    };
    emit(`${pkg}/package.xml`, ctx.templates.render('package.xml.njk', info), root.node);
    emit(`${pkg}/setup.py`, ctx.templates.render('setup.py.njk', { ...info, packages: pythonPackages, scripts }), root.node);
    emit(`${pkg}/setup.cfg`, ctx.templates.render('setup.cfg.njk', info));
    emit(`${pkg}/resource/${pkg}`, '');
    emit(
        `${pkg}/launch/${info.launch}`,
        ctx.templates.render('launch.py.njk', {
            ...info,
            nodes: nodes.map((n) => ({
                ...n,
                executable: n.moduleName,
                params: n.parameters.map((p) => ({ name: p.name, literal: pyLiteral(p) })),
            })),
        }),
        root.node,
    );
}
