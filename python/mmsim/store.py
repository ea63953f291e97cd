"""store.py - a sweep's results as a Parquet dataset (a folder of part files).

Rows are appended as runs finish: each batch is one part file, written
under a temporary name and renamed, so a sweep killed at any moment leaves
only whole parts. Every row has "run_key" (a hash of the run's inputs); a
sweep started again with the same folder reads the keys it holds and skips
those runs. read() drops any repeated key (a part written twice by a
crash between its rename and the next batch keeps one row per run).
"""
import glob
import json
import os
import time

import pandas as pd

PART_GLOB = "part-*.parquet"


class OutError(Exception):
    """An --out that is not a results folder (exit 2), or one that cannot be
    written (external = True: exit 3)."""

    def __init__(self, msg, external=False):
        super().__init__(msg)
        self.external = external


def check_out(out):
    """Before any run: out is a folder of Parquet parts (or not there yet)
    that can be written: a file, a folder whose parts are not Parquet, a
    folder that refuses a file (read-only, /proc) are OutError."""
    if out is None:
        return
    if os.path.exists(out) and not os.path.isdir(out):
        raise OutError("--out %s: a file; --out is a folder of Parquet parts (a new name makes one)" % out)
    try:
        read(out)
    except Exception as e:  # pyarrow's errors have no common base: any is a bad part
        raise OutError("--out %s: not a Parquet results folder: %s" % (out, (str(e).splitlines() or [type(e).__name__])[0])) from None
    try:
        os.makedirs(out, exist_ok=True)
        probe = os.path.join(out, ".probe-%d.tmp" % os.getpid())
        with open(probe, "w"):
            pass
        os.unlink(probe)
    except OSError as e:
        raise OutError("--out %s: cannot write: %s" % (out, e.strerror), external=True) from None


def read(out):
    """Every row of the dataset at out (a folder, or a single Parquet file)."""
    if out is None or not os.path.exists(out):
        return pd.DataFrame()
    files = [out] if os.path.isfile(out) else sorted(glob.glob(os.path.join(out, PART_GLOB)))
    if not files:
        return pd.DataFrame()
    df = pd.concat([pd.read_parquet(f) for f in files], ignore_index=True)
    if "run_key" in df.columns:
        df = df.drop_duplicates("run_key", keep="first").reset_index(drop=True)
    return df


def done_keys(out):
    """The run keys the dataset at out already holds."""
    df = read(out)
    return set(df["run_key"]) if "run_key" in df.columns else set()


class Writer:
    """Appends rows to the dataset folder out, one part file per flush."""

    def __init__(self, out, flush_rows=16, flush_s=2.0):
        self.out, self.flush_rows, self.flush_s = out, flush_rows, flush_s
        self.rows, self.last = [], time.monotonic()
        if out is not None:
            if os.path.isfile(out):
                raise ValueError("%s: a file; --out is a folder of Parquet parts" % out)
            os.makedirs(out, exist_ok=True)

    def add(self, row):
        self.rows.append(row)
        if len(self.rows) >= self.flush_rows or time.monotonic() - self.last >= self.flush_s:
            self.flush()

    def flush(self):
        self.last = time.monotonic()
        if self.out is None or not self.rows:
            self.rows = []
            return
        df = to_frame(self.rows)
        name = "part-%d-%d-%06d.parquet" % (time.time_ns(), os.getpid(), len(self.rows))
        tmp = os.path.join(self.out, "." + name + ".tmp")
        try:
            df.to_parquet(tmp, index=False)
            os.replace(tmp, os.path.join(self.out, name))
        except OSError as e:
            if os.path.exists(tmp):
                os.unlink(tmp)
            raise OutError("--out %s: cannot write: %s" % (self.out, e.strerror), external=True) from None
        self.rows = []


# Columns that hold text when they hold anything: the inputs given as paths,
# names and hashes, and a failed run's error. Every other column mmsim's JSON
# may leave null (best_run_s, first_run_s, a lap's figures) is a number.
TEXT_COLUMNS = {"run_key", "maze", "maze_sha256", "driver", "robot", "robot_sha256", "config",
                "config_sha256", "extra_args", "run_error"}


def to_frame(rows):
    """Rows (flat dicts) as a DataFrame; lists and dicts left in a value are
    stored as their JSON text, so every column has one Parquet type. A column
    with no value in these rows gets its type all the same (text or a float),
    not Parquet's null type: a reader that takes the dataset's schema from
    its first part file (pandas.read_parquet on the folder, DuckDB) would
    otherwise refuse the later parts' numbers."""
    flat = [{k: (json.dumps(v, sort_keys=True) if isinstance(v, (list, dict)) else v)
             for k, v in r.items()} for r in rows]
    df = pd.DataFrame(flat)
    for col in df.columns:
        if df[col].isna().all():
            df[col] = df[col].astype("string" if col in TEXT_COLUMNS else "float64")
    return df
