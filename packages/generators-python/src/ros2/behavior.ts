import type { BehaviorGenerator, BehaviorGeneratorFactory, BehaviorResult, OutputSink } from '@maa/generator-core';
import { automataGenerator } from '../behavior/automata.js';
import { robotArmGenerator } from '../behavior/robotarm.js';
import { ROS2_LINE_LENGTH } from './model/imports.js';
import { MODEL_PACKAGE, rosPackageName } from './naming.js';

/**
 * ros2.AutomataBehavior and ros2.RobotArmBehavior: the shared behavior generators of
 * `src/behavior/` (the same ones timesync.* uses), with their output placed inside the
 * ament_python package of ros2.Components: `<pkg>/<pkg>/model/<model package>/<module>.py`,
 * imported as `<pkg>.model.<model package>.<module>`. ros2.Components wraps the classes in rclpy
 * nodes (and gives a RobotArm executor the simulator's arm, maa_ros2.RosArm).
 */

export function wrapBehaviorGenerator(inner: BehaviorGenerator): BehaviorGenerator {
    return {
        kind: 'behavior',
        rules: inner.rules,
        async generate(behavior, ctx) {
            if (!ctx.platform) throw new Error('ros2 behavior generators need the platform (requires: platform)');
            const pkg = rosPackageName(ctx.platform);
            const files: string[] = [];
            const out: OutputSink = {
                file(path, options) {
                    files.push(path);
                    return ctx.out.file(`${pkg}/${pkg}/${MODEL_PACKAGE}/${path}`, options);
                },
            };
            const result: BehaviorResult = (await inner.generate(behavior, { ...ctx, out })) ?? {};
            const module = typeof result.module === 'string' ? `${pkg}.${MODEL_PACKAGE}.${result.module}` : undefined;
            return { ...result, ...(module ? { module } : {}), files };
        },
    };
}

export const automataBehavior: BehaviorGeneratorFactory = () => wrapBehaviorGenerator(automataGenerator(ROS2_LINE_LENGTH));

export const robotArmBehavior: BehaviorGeneratorFactory = () => wrapBehaviorGenerator(robotArmGenerator(ROS2_LINE_LENGTH));
