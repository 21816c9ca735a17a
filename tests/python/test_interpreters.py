"""`import cosim` works in Debian's Python (the build's) and in another CPython 3.11 on PATH
(pyenv's here), which borrows Debian's NumPy (python/cosim/__init__.py)."""
import os
import shutil
import subprocess
import sys

import pytest



def same_abi(python):
    """Whether `python` is a CPython of this one's version (the extension's ABI)."""
    p = subprocess.run([python, "-c", "import sys; print(sys.version_info[:2])"],
                       capture_output=True, text=True, timeout=30)
    return p.returncode == 0 and p.stdout.strip() == str(tuple(sys.version_info[:2]))


INTERPRETERS = sorted(p for p in {sys.executable, "/usr/bin/python3", shutil.which("python3")}
                      if p and os.path.exists(p) and same_abi(p))


@pytest.mark.parametrize("python", INTERPRETERS)
def test_import_cosim_and_numpy(python):
    code = "import cosim, numpy; print(cosim.plan(planner='astar').path.shape[1])"
    p = subprocess.run([python, "-c", code], capture_output=True, text=True, timeout=60,
                       env=dict(os.environ))
    assert p.returncode == 0, p.stderr
    assert p.stdout == "3\n"


@pytest.mark.parametrize("python", INTERPRETERS)
def test_a_script_may_import_numpy_before_cosim(python):
    # build/python/sitecustomize.py borrows Debian's NumPy at start-up when the interpreter has
    # none, so a script's usual `import numpy as np` first line works too.
    code = "import numpy as np\nimport cosim\nprint(np.zeros(3).shape, cosim.DEFAULT_SCENARIO != '')"
    p = subprocess.run([python, "-c", code], capture_output=True, text=True, timeout=60,
                       env=dict(os.environ))
    assert p.returncode == 0, p.stderr
    assert p.stdout == "(3,) True\n"
