"""Solving: load a problem file (every rule of the format), build the body, run
its kind, convert the answers. May import core, physics and kinds."""
