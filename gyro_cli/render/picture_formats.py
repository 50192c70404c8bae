"""The picture file formats gyro writes, by file suffix (matplotlib's names)."""

FORMATS = {".png": "png", ".svg": "svg", ".pdf": "pdf"}
