# %% [markdown]
# # A scene's answer
#
# `restitution scene FILE --out DIR` as a pipeline step: the library reads and answers the scene
# (restitution.dem.scene), this writes the JSON, the input lines and the text table.

# %%
import json

from restitution_workflow.pipeline import start, write_text

from restitution.cli import scene_table
from restitution.dem.scene import answer_scene
from restitution.dem.scene.file import read_scene

start(snakemake)

# %% the answer: every contact of the scene, its cheapest model within the tolerance
res = answer_scene(read_scene(snakemake.input.scene))

# %% the files
write_text(snakemake.output.json, json.dumps(res, separators=(", ", ": ")) + "\n")
write_text(snakemake.output.lines, "\n".join(res["input_lines"]) + "\n")
write_text(snakemake.output.table, scene_table(res))
