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


def test_install_user_path_says_when_it_repoints_import_cosim_from_another_checkout(tmp_path):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONNOUSERSITE")}
    env["PYTHONUSERBASE"] = str(tmp_path / "userbase")
    other = tmp_path / "other-checkout" / "build" / "python"
    (other / "cosim").mkdir(parents=True)
    first = subprocess.run(["bash", SCRIPT, str(other), sys.executable], capture_output=True,
                           text=True, timeout=60, env=env)
    assert first.returncode == 0, first.stderr
    assert f"loads {other}/cosim" in first.stdout
    again = subprocess.run(["bash", SCRIPT, PACKAGE_DIR, sys.executable], capture_output=True,
                           text=True, timeout=60, env=env)
    assert again.returncode == 0, again.stderr
    assert f"now loads {PACKAGE_DIR}/cosim, no longer {other}/cosim" in again.stdout, again.stdout
    same = subprocess.run(["bash", SCRIPT, PACKAGE_DIR, sys.executable], capture_output=True,
                          text=True, timeout=60, env=env)
    assert "no longer" not in same.stdout and "loads" not in same.stdout, same.stdout


def test_build_info_names_the_loaded_package_and_its_checkout():
    info = cosim.build_info()
    assert info["package"] == os.path.dirname(os.path.abspath(cosim.__file__))
    assert os.path.isfile(info["extension"])
    assert os.path.dirname(info["extension"]) == info["package"]
    assert os.path.isfile(os.path.join(info["checkout"], "experiments", "scenarios", "default.yaml"))
    assert info["version"] == cosim.__version__


def test_install_user_path_refuses_a_folder_without_the_package(tmp_path):
    p = subprocess.run(["bash", SCRIPT, str(tmp_path)], capture_output=True, text=True,
                       timeout=60)
    assert p.returncode == 2
    assert "no built package cosim/ there" in p.stderr
