"""Checking: expected answers and tolerances, root matching and slip
diagnosis, grading answer sheets; results as data. May import solving and
below; prints nothing."""
