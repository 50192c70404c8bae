"""Physics on plain floats: the exact nutation solution, theta(t), the
integrator of Euler's equations, shared algebra. No files, no units, no
printing; imports only the standard library, numpy, scipy and core.errors.

What `gyro check` and `gyro solve` run needs the standard library alone: numpy and
scipy are imported inside the functions that draw and simulate (theta(t) over a grid,
the integrator), so a check of a bank never loads them."""
