"""``python -m gyro_cli`` is ``gyro``."""

from .cli import main

main(prog_name="gyro")
