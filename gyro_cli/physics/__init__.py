"""Physics: the exact nutation solution, theta(t), the integrator of Euler's
equations, shared algebra, and the formulas the kinds print, written once for
floats and formula trees (core/generic.py). No files, no units, no printing;
imports only the standard library, numpy, scipy, core.errors and core.generic.

What `gyro check` and `gyro solve` run needs the standard library alone: numpy and
scipy serve only what draws and simulates (motion.py's theta(t) over a grid,
simulate.py's and rolling_motion.py's integrators, nutation.py's vectorised rates), so
a check of a bank never loads them (tests/test_check_scale.py)."""
