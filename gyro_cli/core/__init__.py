"""Core: errors, units, safe files, the declarations of keys and answers, the
given data, the body and the worked-answer model. Imports nothing of gyro_cli
above it."""
