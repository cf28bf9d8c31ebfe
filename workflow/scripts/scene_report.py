# %% [markdown]
# # A scene's report
#
# From the answer of `restitution scene` (scene.json): per material pair, eps(v) of every candidate
# model tried against the target and its deviation against the tolerance band; per contact,
# the contact time and the time step against speed; the table and the input lines. One HTML page
# beside its figures. Reads the answer only, computes nothing.

# %%
import html
import math
from pathlib import Path

import numpy as np
from restitution_workflow.pipeline import read_json, save_figure, setup_matplotlib, start, write_text

start(snakemake)
plt = setup_matplotlib()
res = read_json(snakemake.input.json)
out = snakemake.output
tol = res["tolerance"]
curves = res["curves"]
cols = min(3, len(curves))
rows = math.ceil(len(curves) / cols)

# %% eps(v) of every model against the target, and its deviation against the tolerance band
def per_pair(draw, ylabel, pdf, png):
    """One panel per material pair, ``draw(ax, speeds, curve)`` filling each."""
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.0 * rows), squeeze=False, sharex=True)
    for ax, c in zip(axes.flat, curves):
        draw(ax, np.array(c["speeds"]), c)
        ax.set_xscale("log")
        ax.set_title(" - ".join(c["pair"]), fontsize=9)
        ax.set_ylabel(ylabel)
        ax.legend(fontsize=6, loc="best")
    for ax in axes.flat[len(curves):]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("impact speed (m/s)")
    fig.tight_layout()
    save_figure(fig, pdf, png)
    plt.close(fig)


def eps_panel(ax, v, c):
    target = np.array(c["target"])
    ax.fill_between(v, target - tol, target + tol, color="0.88", label="target ± tolerance")
    ax.plot(v, target, color="k", lw=1.2, label="target")
    for r in c["models"]:
        ax.plot(v, r["eps"], lw=1.4, ls="-" if r["accepted"] else "--",
                label=f"{r['name']} ({'accepted' if r['accepted'] else 'rejected'})")


def deviation_panel(ax, v, c):
    ax.axhspan(-tol, tol, color="0.88", label="tolerance")
    for r in c["models"]:
        ax.plot(v, np.array(r["eps"]) - np.array(c["target"]), lw=1.4, ls="-" if r["accepted"] else "--",
                label=r["name"])
    ax.axhline(0.0, color="k", lw=0.6)


per_pair(eps_panel, "eps", out.eps_pdf, out.eps_png)
per_pair(deviation_panel, "eps - target", out.dev_pdf, out.dev_png)

# %% contact time and time step against speed, per contact
met = [c for c in res["contacts"] if c["chosen"] is not None]
fig, ax = plt.subplots(figsize=(7.0, 4.5))
for i, c in enumerate(met):
    color = plt.cm.viridis(i / max(1, len(met) - 1))
    ax.plot(c["speeds"], c["contact_time"], color=color, lw=1.0, label=f"{c['a']}-{c['b']}" if len(met) <= 12 else None)
    ax.plot(c["speeds"], [c["dt"]] * len(c["speeds"]), color=color, lw=0.8, ls=":")
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("impact speed (m/s)")
ax.set_ylabel("seconds")
ax.set_title("contact time (solid) and the time step for the tolerance (dotted), per contact", fontsize=9)
if len(met) <= 12:
    ax.legend(fontsize=6, ncol=2)
fig.tight_layout()
save_figure(fig, out.dt_pdf, out.dt_png)
plt.close(fig)

# %% the page
table = Path(snakemake.input.table).read_text()
figures = "".join(f'<h2>{html.escape(title)}</h2>\n<img src="{Path(png).name}" alt="{html.escape(title)}" style="max-width:100%">\n'
                  for title, png in (("eps(v) of every model tried against the target", out.eps_png),
                                     ("Deviation from the target against the tolerance band", out.dev_png),
                                     ("Contact time and time step against speed", out.dt_png)))
verdict = ("every contact has a model within the tolerance" if res["met"]
           else "some contacts are not met (no model within the tolerance, or an overlap that breaks the "
                "code's geometry): see the table")
page = f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>Scene {html.escape(res['scene'])}</title></head>
<body style="font-family: sans-serif; max-width: 70em; margin: auto">
<h1>Scene {html.escape(res['scene'])}</h1>
<p>{html.escape(res['code'])}, tolerance {tol:g} on eps (absolute) over speeds {res['speeds'][0]:g} to
{res['speeds'][1]:g}: {verdict}. Checked: {html.escape(res['check'])}. The small example scene's settings
are run in LAMMPS by the project's tests (tests/library/test_scene_lammps.py).</p>
{figures}<h2>Contacts, models tried and input lines</h2>
<pre>{html.escape(table)}</pre>
</body></html>
"""
write_text(out.html, page)
