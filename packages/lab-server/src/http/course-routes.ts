// Course routes of the instructor (docs/lab.md "Routes").
import { HttpError, sendJson } from '@maa/ide-server/http';
import { userView } from './body.js';
import type { LabRoutes } from './routes.js';

export function addCourseRoutes(routes: LabRoutes): void {
    routes.add({
        method: 'GET',
        path: '/api/courses/:course/students',
        access: 'instructor',
        handler: async ({ res, store, params }) => {
            const name = params['course'] ?? '';
            const course = await store.findCourse(name);
            if (!course) throw new HttpError(404, `there is no course ${JSON.stringify(name)}`);
            const students = (await store.listEnrolled(course.id)).filter((u) => u.role === 'student');
            sendJson(res, 200, { course: { name: course.name, title: course.title }, students: students.map(userView) });
        },
    });
}
