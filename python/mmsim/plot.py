"""plot.py - one picture of a sweep's table: what succeeded and what changed it.

data(df) computes every plotted number (so a test can compare them with
the table): per maze and per value of each varied key, the success rate
(reached_goal) and the contact rate (collisions > 0), each over the runs
that gave a result; best_run_s of the runs that reached the goal, per maze;
and each varied key's sensitivity: the least-squares slope of best_run_s
against the key's value, times the values' standard deviation (seconds of
best run per one standard deviation of the key).
"""
import os
import math

import numpy as np


def vary_keys(df):
    return [c[len("vary."):] for c in df.columns if c.startswith("vary.")]


def rates(df, by):
    """{group: {"runs", "success_rate", "contact_rate"}} over the rows with a result."""
    ok = df[df["run_error"].isna()] if "run_error" in df.columns else df
    out = {}
    for value, g in ok.groupby(by, sort=True):
        n = len(g)
        out[str(value)] = {"runs": n,
                           "success_rate": float((g["reached_goal"] == True).sum()) / n,  # noqa: E712
                           "contact_rate": float((g["collisions"].fillna(0) > 0).sum()) / n}
    return out


def sensitivity(df, key):
    g = df[(df.get("reached_goal") == True) & df["best_run_s"].notna()]  # noqa: E712
    x = g["vary." + key].astype(float).to_numpy()
    y = g["best_run_s"].astype(float).to_numpy()
    if len(x) < 2 or np.std(x) == 0:
        return {"slope_s_per_unit": None, "s_per_sd": None, "runs": int(len(x))}
    slope = float(np.polyfit(x, y, 1)[0])
    return {"slope_s_per_unit": slope, "s_per_sd": slope * float(np.std(x)), "runs": int(len(x))}


def data(df):
    keys = vary_keys(df)
    ok = df[df["reached_goal"] == True] if "reached_goal" in df.columns else df.iloc[:0]  # noqa: E712
    doc = {"runs": int(len(df)),
           "failed": int(df["run_error"].notna().sum()) if "run_error" in df.columns else 0,
           "per_maze": rates(df, "maze"),
           "per_value": {k: rates(df, "vary." + k) for k in keys},
           "best_run_s": {str(m): [float(v) for v in g["best_run_s"].dropna()] for m, g in ok.groupby("maze")},
           "sensitivity": {k: sensitivity(df, k) for k in keys if is_numeric(df["vary." + k])}}
    return doc


def is_numeric(col):
    try:
        col.astype(float)
        return True
    except (TypeError, ValueError):
        return False


def draw(doc, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    keys = list(doc["per_value"])
    rows = 2 + math.ceil(len(keys) / 2)
    fig, axes = plt.subplots(rows, 2, figsize=(11, 3.2 * rows), squeeze=False)
    bars(axes[0][0], doc["per_maze"], "per maze")
    laps(axes[0][1], doc["best_run_s"])
    sens(axes[1][0], doc["sensitivity"])
    axes[1][1].axis("off")
    axes[1][1].text(0, 0.5, "%d runs, %d without a result" % (doc["runs"], doc["failed"]), fontsize=11)
    for i, k in enumerate(keys):
        bars(axes[2 + i // 2][i % 2], doc["per_value"][k], k)
    if len(keys) % 2:
        axes[-1][1].axis("off")
    fig.tight_layout()
    # whole or not at all: a temporary beside path, renamed over it
    tmp = "%s.tmp.%d" % (path, os.getpid())
    try:
        fig.savefig(tmp, format=os.path.splitext(path)[1].lstrip(".").lower() or "png")
        os.replace(tmp, path)
    finally:
        plt.close(fig)
        if os.path.exists(tmp):
            os.unlink(tmp)


def bars(ax, per, title):
    names = list(per)
    x = np.arange(len(names))
    ax.bar(x - 0.2, [per[n]["success_rate"] for n in names], 0.4, label="success (goal reached)")
    ax.bar(x + 0.2, [per[n]["contact_rate"] for n in names], 0.4, label="runs with wall contact")
    ax.set_xticks(x)
    ax.set_xticklabels([short(n) for n in names], rotation=30, ha="right", fontsize=7)
    ax.set_ylim(0, 1.05)
    ax.set_ylabel("fraction of runs")
    ax.set_title("success and contact rate, " + title, fontsize=9)
    ax.legend(fontsize=7)


def laps(ax, best):
    names = [m for m in best if best[m]]
    if names:
        ax.boxplot([best[m] for m in names], labels=[short(m) for m in names])
    ax.set_ylabel("best run, s")
    ax.set_title("best run time per maze (runs that reached the goal)", fontsize=9)
    ax.tick_params(axis="x", labelrotation=30, labelsize=7)


def sens(ax, sensitivity):
    names = [k for k in sensitivity if sensitivity[k]["s_per_sd"] is not None]
    ax.barh(range(len(names)), [sensitivity[k]["s_per_sd"] for k in names])
    ax.set_yticks(range(len(names)))
    ax.set_yticklabels(names, fontsize=7)
    ax.axvline(0, color="k", lw=0.5)
    ax.set_xlabel("change of best run, s per standard deviation of the key")
    ax.set_title("sensitivity of best-run time", fontsize=9)


def short(name):
    name = str(name)
    try:
        return "%.6g" % float(name)
    except ValueError:
        pass
    return name.rsplit("/", 1)[-1] if "/" in name else name[:14]
