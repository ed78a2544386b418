// Breakpoints in the browser IDE (issue 19, docs/simulation.md "Breakpoints"): a lock-step run of
// the example lists the automata of the run in the simulate view's breakpoints section; a
// breakpoint on the Controller's Toasting -> Serving transition pauses the run with Serving
// active: the view names the breakpoint, the status line says paused, the diagram's state chip of
// ctrl shows Serving. Each gets { page, url, workspace, shot(name) } (run.mjs).
import { fail } from './host-kit.mjs';
import { startLockstepRun, until } from './lib.mjs';

const text = async (locator) => ((await locator.textContent().catch(() => '')) ?? '').trim();

export const breakpointScenarios = [
    {
        id: 'b1-breakpoint',
        name: 'breakpoints (lock-step): a breakpoint on Toasting -> Serving pauses the run with Serving active',
        async run({ page, url, shot }) {
            const { view, diagram } = await startLockstepRun(page, url, { diagram: true });
            const pause = view.locator('[data-testid=sim-pause]');
            // the breakpoints section appears once the run's automata table is there
            const section = view.locator('[data-testid=breakpoints]');
            await section.waitFor({ state: 'visible', timeout: 60_000 });
            // stop the run, set the breakpoint, start it over from the beginning (the reset keeps the breakpoints)
            await pause.click();
            if (!(await section.evaluate((d) => d.open))) await section.locator('summary').click();
            const box = view.locator('[data-testid=bp-ctrl-transition-2]');
            await box.waitFor({ timeout: 10_000 });
            if ((await text(box.locator('xpath=..'))).indexOf('Toasting → Serving') < 0)
                await fail(`the transition 2 of ctrl is not Toasting → Serving: ${await text(box.locator('xpath=..'))}`);
            await box.check();
            await until(
                page,
                'the breakpoints count does not show the checked one',
                async () => /\(1\)/.test(await text(section.locator('summary'))),
                10_000,
            );
            await view.locator('[data-testid=sim-reset]').click();
            const resume = view.locator('[data-testid=sim-resume]');
            await until(page, 'Resume is not enabled after the reset', () => resume.isEnabled(), 60_000);
            await resume.click();
            await shot('set');

            // the run pauses at the breakpoint: the view names it, the status says paused
            const hit = view.locator('[data-testid=breakpoint-hit]');
            await until(
                page,
                'the run did not pause at the breakpoint within 300 s',
                async () => /Toasting → Serving/.test(await text(hit)),
                300_000,
            );
            if ((await text(hit)) !== 'Paused at breakpoint ctrl: Toasting → Serving')
                await fail(`the breakpoint line says "${await text(hit)}"`);
            await until(
                page,
                'the status line does not say paused',
                async () => /^paused/.test(await text(view.locator('[data-testid=sim-status]'))),
                10_000,
            );
            if (!(await view.locator('.maa-bp-hit', { hasText: 'Toasting → Serving' }).isVisible()))
                await fail('the breakpoint row is not marked');
            await shot('paused');

            // the diagram shows Serving active on ctrl (its state chip)
            await page.locator('.tabs-container .tab', { hasText: 'MontiArc Diagram' }).first().click();
            await diagram
                .locator('.maa-state-active', { hasText: 'Serving' })
                .first()
                .waitFor({ state: 'visible', timeout: 30_000 })
                .catch(() => fail('the diagram shows no Serving state chip'));
            await shot('diagram');

            // clear the breakpoint and stop the run
            await page.locator('.tabs-container .tab', { hasText: 'MontiArc Simulation' }).first().click();
            await box.uncheck();
            await view.locator('[data-testid=sim-stop]').click();
        },
    },
];
