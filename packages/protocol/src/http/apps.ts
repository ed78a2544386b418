/** `GET /api/apps`: the application configurations (`.arcapp`) of the workspace. */
import { Type, type Static } from '@sinclair/typebox';

export const AppPlatformInfo = Type.Object({
    name: Type.String(),
    /** The generator family (`ros2`, `timesync`): the first segment of its generators' names. */
    kind: Type.String(),
    /** The platform's generators (`timesync.Components`). */
    generators: Type.Array(Type.String()),
});
export type AppPlatformInfo = Static<typeof AppPlatformInfo>;

export const AppInfo = Type.Object({
    /** The `.arcapp` file, relative to the workspace. */
    path: Type.String(),
    name: Type.String(),
    /** The root component as written in the file (`toast.ToastServiceRobot`). */
    component: Type.String(),
    platforms: Type.Array(AppPlatformInfo),
});
export type AppInfo = Static<typeof AppInfo>;

export const AppsAnswer = Type.Object({ apps: Type.Array(AppInfo) });
export type AppsAnswer = Static<typeof AppsAnswer>;
