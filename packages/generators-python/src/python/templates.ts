import { fileURLToPath } from 'node:url';
import { createTemplateRenderer } from '@maa/generator-core/node';
import type { AutomatonClassView, ComputeClassView, ModuleView } from '../behavior/views.js';
import type { RobotArmClassView } from '../behavior/views.js';
import type {
    AppModuleView,
    ComponentClassesView,
    DataTypeView as DataTypeChunkView,
    DataTypesModuleView,
    HandwrittenUserView,
    ModeTransitionView,
} from '../timesync/views.js';

/**
 * The Python templates of the shared behavior emitters and the timesync generator
 * (`templates/behavior`, `templates/timesync`), rendered with generator-core's shared Nunjucks
 * environment (`createTemplateRenderer`, the one the orchestrator gives each generator for its
 * manifest's `templates` folder). One renderer for the process: its loader caches each compiled
 * template, so a template is compiled once however many generators and runs use it. The behavior
 * emitters are also called by the ros2 generator, whose own renderer only sees `templates/ros2`.
 */
const renderer = createTemplateRenderer(fileURLToPath(new URL('../../templates', import.meta.url)));

/** Each template and the view model it renders (`v` in the template). */
export interface PythonTemplates {
    'behavior/module.py.njk': ModuleView;
    'behavior/compute.njk': ComputeClassView;
    'behavior/automaton.njk': AutomatonClassView;
    'behavior/robotarm.njk': RobotArmClassView;
    'timesync/component.njk': ComponentClassesView;
    'timesync/mode-transition.njk': ModeTransitionView;
    'timesync/handwritten.py.njk': HandwrittenUserView;
    'timesync/app.py.njk': AppModuleView;
    'timesync/datatypes-module.njk': DataTypesModuleView;
    'timesync/datatype.njk': DataTypeChunkView;
}

/** Renders a template with its view model. */
export function renderPython<T extends keyof PythonTemplates>(template: T, view: PythonTemplates[T]): string {
    return renderer.render(template, { v: view });
}

/** The lines of a rendered template that ends with a newline (for the emitters that return lines). */
export function renderLines<T extends keyof PythonTemplates>(template: T, view: PythonTemplates[T]): string[] {
    return renderPython(template, view).replace(/\n$/, '').split('\n');
}
