import { describe, expect, it } from 'vitest';
import { importLines, platformTopics } from '../src/ros2/components.js';
import { constantName, fieldName, messageName, rosName } from '../src/ros2/naming.js';

describe('ros2.* helpers', () => {
    it('reads the platform topics a handwritten component declares', () => {
        const text = [
            'class DistanceSensor(DistanceSensorBase):',
            '    SUBSCRIBES: ClassVar[dict[str, str]] = {"/sensors/distance": "std_msgs/msg/Int32", \'/a/b\': \'x/msg/Y\'}',
            '    PUBLISHES: ClassVar[dict[str, str]] = {}',
        ].join('\n');
        expect(platformTopics(text)).toEqual({
            subscribes: [
                { topic: '/sensors/distance', type: 'std_msgs/msg/Int32' },
                { topic: '/a/b', type: 'x/msg/Y' },
            ],
            publishes: [],
        });
        expect(platformTopics('class X:\n    pass\n')).toEqual({ subscribes: [], publishes: [] });
    });

    it('orders imports like ruff (isort): plain imports first, then by module; constants, classes, functions', () => {
        const lines = importLines(
            new Map([
                ['std_msgs.msg', new Set(['Int32'])],
                ['maa_ros2', new Set(['run_node', 'InPort', 'ComponentNode', 'PORT_QOS'])],
                ['app_interfaces.msg', new Set([''])],
                ['app.model.types', new Set(['Mode'])],
            ]),
        );
        expect(lines).toEqual([
            'import app_interfaces.msg',
            'from app.model.types import Mode',
            'from maa_ros2 import PORT_QOS, ComponentNode, InPort, run_node',
            'from std_msgs.msg import Int32',
        ]);
    });

    it('names ROS things as rosidl and rcl want them', () => {
        expect(rosName('ToastServiceRobot')).toBe('toast_service_robot');
        expect(rosName('toasterCtrl')).toBe('toaster_ctrl');
        expect(rosName('2fast')).toBe('x_2fast');
        expect(fieldName('firstName_')).toBe('first_name');
        expect(messageName('toast_color')).toBe('ToastColor');
        expect(constantName('Golden')).toBe('GOLDEN');
    });
});
