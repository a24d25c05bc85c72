"""The build's rlpos for the scripts in this folder, or a one-line exit that names the Python to use.

The binding is built for one interpreter (CMake's Python_EXECUTABLE, Debian's /usr/bin/python3 by
default), and numpy is Debian's package of that interpreter: the python3 first on PATH (pyenv,
conda) may lack both. build/bin/rlpos-python is that interpreter with the binding on its path.
"""
import os
import sys


def import_rlpos(build_dir=None):
    """The rlpos module (of BUILD_DIR/python when given); exits naming the interpreter if absent."""
    if build_dir:
        sys.path.insert(0, os.path.join(build_dir, 'python'))
    try:
        import numpy  # noqa: F401 (rlpos needs it; a missing one is the usual wrong-Python sign)
        import rlpos
    except ImportError as error:
        script = os.path.relpath(sys.argv[0])
        sys.exit(f'{script}: {sys.executable} cannot import {error.name}: run it with '
                 f'build/bin/rlpos-python {script} (the Python the binding was built for)')
    return rlpos
