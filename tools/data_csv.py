"""The generated tables under tools/data/: one writer for the reference generators."""

import os

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data")


def write_rows(name, rows):
    """Writes `rows` (strings, the header first) as the lines of tools/data/`name`; its path."""
    path = os.path.join(DATA, name)
    with open(path, "w") as fh:
        fh.write("\n".join(rows) + "\n")
    return path
