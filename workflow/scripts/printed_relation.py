# %% [markdown]
# # The paper's connection Omega~ = c0 + c1 Omega + c2 Omega^2 (printed c's)
#
# Written as a relation file for figure 4. Later stages add our derived and fitted c's as
# files of the same shape ({"label", "source", "c"}).

# %%
from restitution_workflow.pipeline import start, write_json

from restitution.audit.printed import PRINTED_C

start(snakemake)

# %%
write_json(snakemake.output[0], {
    "kind": "printed",
    "label": r"paper's $c_0, c_1, c_2$",
    "source": "Kim, Sec. V (c0 = 6.0203, c1 = -1.5257, c2 = 0.0256)",
    "c": list(PRINTED_C),
})
