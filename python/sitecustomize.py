"""Start-up hook for interpreters that find build/python through PYTHONPATH or the cosim.pth file
setup.sh writes (docs/python.md).

Python's `site` module imports the first `sitecustomize` on sys.path at start-up, before the
script runs. The extension is built against Debian's Python 3.11, whose NumPy lives in
/usr/lib/python3/dist-packages; another CPython 3.11 on PATH (pyenv's, here the first `python3`)
has the same ABI but no NumPy and does not look there. cosim/__init__.py borrows Debian's NumPy
when cosim is imported, but a script that imports numpy *before* cosim would fail first: so the
borrowing happens here, at start-up, and only when the interpreter has no NumPy of its own
(appended, so the interpreter's own packages still win). Then the sitecustomize this one shadows,
if any (Debian's installs the apport hook), runs as it would have.
"""
import importlib.util
import os
import sys

_DEBIAN_PACKAGES = "/usr/lib/python3/dist-packages"

if (sys.version_info[:2] == (3, 11) and importlib.util.find_spec("numpy") is None
        and os.path.isdir(os.path.join(_DEBIAN_PACKAGES, "numpy"))):
    sys.path.append(_DEBIAN_PACKAGES)


def _run_shadowed_sitecustomize():
    here = os.path.dirname(os.path.abspath(__file__))
    for entry in sys.path:
        candidate = os.path.join(entry or ".", "sitecustomize.py")
        if os.path.abspath(entry or ".") != here and os.path.isfile(candidate):
            with open(candidate) as f:
                exec(compile(f.read(), candidate, "exec"), {"__name__": "sitecustomize"})
            return


try:
    _run_shadowed_sitecustomize()
except Exception:  # a broken hook of the system's must not stop the interpreter (site ignores it too)
    pass
