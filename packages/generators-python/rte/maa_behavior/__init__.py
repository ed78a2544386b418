"""maa-python-behavior: the run-time environment of generated behavior classes.

Every behavior generator of ``@maa/generators-python`` emits one class per component type
that derives from :class:`Behavior` (see docs/runtime.md, "Behavior classes"). Platforms
(python-timesync, ROS 2) wrap these classes; the classes know nothing about them.
"""

from maa_behavior.behavior import Behavior, Emit, NoBehavior
from maa_behavior.jlib import JavaException, JDate, JIterator, JOptional, jcall, jfield, jformat, jhash, jstatic
from maa_behavior.jvm import f32, jcast, jconcat, jdiv, jmod, jordinal, jstr, jushr

__all__ = [
    "Behavior",
    "Emit",
    "JDate",
    "JIterator",
    "JOptional",
    "JavaException",
    "NoBehavior",
    "f32",
    "jcall",
    "jcast",
    "jconcat",
    "jdiv",
    "jfield",
    "jformat",
    "jhash",
    "jmod",
    "jordinal",
    "jstatic",
    "jstr",
    "jushr",
]
