"""Physics on plain floats: the exact nutation solution, theta(t), the
integrator of Euler's equations, shared algebra. No files, no units, no
printing; imports only the standard library, numpy, scipy and core.errors."""
