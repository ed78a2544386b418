// `GET <prefix>`: what the front end needs to know of a workspace besides its files: whose it
// is, whether the sender may write, the exercise (its description, read-only files, app, tests, platforms)
// and the newest test and simulation results.
import { sendJson } from '@maa/ide-server/http';
import type { LabRoutes } from '../http/routes.js';
import { openWorkspaceFor, WS_PREFIX } from './resolve.js';

export function addInfoRoute(routes: LabRoutes): void {
    routes.add({
        method: 'GET',
        path: WS_PREFIX,
        access: 'user',
        handler: async ({ res, store, auth, params }) => {
            const opened = await openWorkspaceFor(store, auth, params);
            const { spec } = opened;
            const [tests, simulation] = await Promise.all([
                store.latestTestResult(opened.workspace.id),
                store.latestSimulationResult(opened.workspace.id),
            ]);
            sendJson(res, 200, {
                prefix: opened.prefix,
                course: opened.course.name,
                exercise: opened.exercise.name,
                owner: opened.owner.login,
                writable: !opened.viewer,
                title: spec.title,
                description: spec.description,
                app: spec.app,
                readOnly: spec.readOnly,
                tests: spec.tests,
                platforms: spec.platforms,
                latestTests: tests ? { passed: tests.passed, failed: tests.failed, at: tests.createdAt } : null,
                latestSimulation: simulation
                    ? { goalReached: simulation.goalReached, simulatedSeconds: simulation.simulatedSeconds, at: simulation.createdAt }
                    : null,
            });
        },
    });
}
