"""What the pytest tests of scripts/ share (tests/test_*.py, run by ctest as
`/usr/bin/python3 -m pytest tests/test_NAME.py`): the source tree and a way to run a script."""
import subprocess
import sys
from pathlib import Path

SOURCE = Path(__file__).resolve().parent.parent
SCRIPTS = SOURCE / "scripts"
# The scripts' own functions, imported where a test needs them in bulk.
sys.path.insert(0, str(SCRIPTS))


def run_script(name, *args):
    """scripts/NAME run with this interpreter; its CompletedProcess (text output captured)."""
    return subprocess.run([sys.executable, str(SCRIPTS / name), *map(str, args)],
                          capture_output=True, text=True)
