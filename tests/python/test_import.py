"""Importing the module under an interpreter it was not built for says which one it was built for."""

import os
import subprocess
import sys

import hydrodda

# The interpreter without NumPy: a python3 that is not the one the module was built for (a
# virtual environment, pyenv, conda) and lacks its NumPy, or runs another Python altogether.
WITHOUT_NUMPY = "import sys; sys.modules['numpy'] = None; import hydrodda"
WITHOUT_EXTENSION = "import sys; sys.modules['hydrodda._hydrodda'] = None; import hydrodda"


def test_an_interpreter_without_numpy_is_told_which_one_the_module_is_built_for():
    from hydrodda._built_for import INTERPRETER, VERSION

    assert os.path.isabs(INTERPRETER) and VERSION.startswith("3.")
    for script, missing in ((WITHOUT_NUMPY, "numpy"), (WITHOUT_EXTENSION, "hydrodda._hydrodda")):
        child = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=os.environ,
                               timeout=60)
        assert child.returncode == 1
        last = child.stderr.strip().splitlines()[-1]
        assert last.startswith("ModuleNotFoundError: hydrodda is built for ")
        assert f"{INTERPRETER} (Python {VERSION})" in last
        assert sys.executable in last and missing in last


def test_the_module_is_imported_under_the_interpreter_it_is_built_for():
    from hydrodda._built_for import INTERPRETER

    assert os.path.realpath(INTERPRETER) == os.path.realpath(sys.executable)
    assert hydrodda.Scenario is not None
