"""Physics on plain floats: no files, no units, no printing.

Modules here may import only the standard library, numpy and scipy, and each
other; the kinds above them call these functions with SI floats.
"""
