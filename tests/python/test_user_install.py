"""`./setup.sh` makes `import cosim` work without PYTHONPATH (python/install_user_path.sh writes
cosim.pth into the user's site-packages; docs/python.md). Tried with a user base of its own, so
the real user's site-packages are not touched."""
import os
import subprocess
import sys

import cosim

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "python", "install_user_path.sh")
PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(cosim.__file__)))


def import_cosim(env, cwd):
    code = "import cosim; print(cosim.__file__)"
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=60, env=env, cwd=cwd)


def test_install_user_path_makes_cosim_importable_without_pythonpath(tmp_path):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONNOUSERSITE")}
    env["PYTHONUSERBASE"] = str(tmp_path / "userbase")
    before = import_cosim(env, tmp_path)
    assert before.returncode != 0 and "No module named 'cosim'" in before.stderr, before.stdout

    p = subprocess.run(["bash", SCRIPT, PACKAGE_DIR, sys.executable], capture_output=True,
                       text=True, timeout=60, env=env)
    assert p.returncode == 0, p.stderr
    after = import_cosim(env, tmp_path)
    assert after.returncode == 0, after.stderr
    assert after.stdout.strip() == os.path.join(PACKAGE_DIR, "cosim", "__init__.py")


def test_install_user_path_refuses_a_folder_without_the_package(tmp_path):
    p = subprocess.run(["bash", SCRIPT, str(tmp_path)], capture_output=True, text=True,
                       timeout=60)
    assert p.returncode == 2
    assert "no built package cosim/ there" in p.stderr
