"""The scale-out guide's process-pool example runs as a saved script (issue 45).

The site's build runs the guide's Python blocks inside its own process, where the pool's
workers never import the block; a reader saves the example to a file and runs
``python file.py``, where the forkserver's (or spawn's) workers import that file again as
their main module.  Without ``if __name__ == "__main__":`` the example then dies in the
bootstrapping phase (``RuntimeError``, then ``BrokenProcessPool``).  This test does what the
reader does: the very block of docs/guide/scale-out.md, written to a file in a scratch
directory and run by a fresh interpreter.
"""

import importlib.util
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
GUIDE = ROOT / "docs/guide/scale-out.md"
_SPEC = importlib.util.spec_from_file_location("docs_hook_run", ROOT / "docs/hooks/run.py")
RUN = importlib.util.module_from_spec(_SPEC)
_SPEC.loader.exec_module(RUN)


def _pool_example() -> str:
    """The guide's one Python block that starts a process pool, as the build runs it."""
    blocks = [
        match["body"]
        for match in RUN.BLOCK.finditer(GUIDE.read_text())
        if match["lang"] == "python" and "executor_for(" in match["body"]
    ]
    assert len(blocks) == 1, f"{GUIDE.name}: {len(blocks)} Python blocks start a pool, not one"
    return blocks[0]


def test_the_guides_pool_example_runs_as_a_saved_script(tmp_path):
    script = tmp_path / "scale_example.py"
    script.write_text(_pool_example())
    done = subprocess.run(
        [sys.executable, str(script)],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=240,
    )
    assert done.returncode == 0, (
        f"`python {script.name}` (the example of {GUIDE.name}) exited with {done.returncode}:\n"
        f"{done.stdout}\n{done.stderr}"
    )
    assert "bit-identical: True" in done.stdout, done.stdout
    assert sorted(p.name for p in tmp_path.iterdir()) == [script.name]  # it wrote nothing
