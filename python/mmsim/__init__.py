"""mmsim - run the micromouse simulator from Python, and sweeps of runs on Dask.

  mmsim.run(maze, driver=..., seed=..., robot=..., config=..., extra_args=[...])
      one run of build/mmsim --json: its JSON as a dict ("exit_code" added)
  mmsim.sweep(mazes, seeds, vary={KEY: SPEC}, drivers=[...], out=..., scheduler=None, workers=2)
      mazes x seeds x varied values x drivers: a pandas DataFrame, one row per run

python/README.md describes both, the --vary SPEC forms and the mmsweep command.
"""
from .runner import run, default_mmsim
from .variations import SpecError
from .planning import plan
from .sweep import sweep, execute, ExternalError
from .store import read, OutError

__all__ = ["run", "sweep", "plan", "execute", "read", "default_mmsim", "SpecError", "ExternalError", "OutError"]
