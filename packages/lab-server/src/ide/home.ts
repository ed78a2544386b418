// The lab's start page (`GET /`, where the login page leads): for a student the released
// exercises of their courses, each a link to the IDE of their own workspace; for an instructor
// every course's dashboard and its released exercises. A plain page under the lab's page policy
// (no script).
import type { EnrolledExercise, User } from '../storage/index.js';
import type { LabRoutes } from '../http/routes.js';
import { sendLabPage } from '../http/pages.js';
import { escapeHtml } from './html.js';

const segment = encodeURIComponent;

/** The start page's HTML for `user` and the exercises of their courses. */
export function homePage(user: Pick<User, 'login' | 'name' | 'role'>, exercises: readonly EnrolledExercise[]): string {
    const courses = new Map<string, { title: string; exercises: EnrolledExercise[] }>();
    for (const e of exercises) {
        const course = courses.get(e.course) ?? { title: e.courseTitle, exercises: [] };
        course.exercises.push(e);
        courses.set(e.course, course);
    }
    const sections = [...courses].map(([name, course]) => {
        const instructor = user.role === 'instructor';
        const items = course.exercises
            .map((e) => {
                const title = escapeHtml(e.title);
                const ide = `/ide/${segment(e.course)}/${segment(e.exercise)}/${segment(user.login)}/`;
                return `<li>${instructor ? title : `<a href="${ide}">${title}</a>`} <small>(${escapeHtml(e.exercise)})</small></li>`;
            })
            .join('\n');
        const dashboard = instructor ? `<p><a href="/dashboard/${segment(name)}">Dashboard of ${escapeHtml(course.title)}</a></p>` : '';
        return `<h2>${escapeHtml(course.title)}</h2>\n${dashboard}\n<ul>\n${items}\n</ul>`;
    });
    const body = sections.length > 0 ? sections.join('\n') : '<p>No exercise has been released in your courses yet.</p>';
    return `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width"><title>maa-lab</title></head>
<body style="font-family: sans-serif; max-width: 40em; margin: 3em auto">
<h1>Hello, ${escapeHtml(user.name || user.login)}</h1>
${body}
</body></html>
`;
}

export function addHomePage(routes: LabRoutes): void {
    routes.add({
        method: 'GET',
        path: '/',
        access: 'user',
        handler: async ({ res, store, auth }) => {
            const everyCourse = auth.user.role === 'instructor';
            sendLabPage(res, homePage(auth.user, await store.listReleasedExercises(everyCourse ? undefined : auth.user.id)));
        },
    });
}
