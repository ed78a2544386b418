"""maa-sim: the simulation sidecar of the MontiArcAutomaton workbench."""

__version__ = "0.1.0"
