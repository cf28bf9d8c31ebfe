# %% [markdown]
# # The arXiv bundle
#
# What arXiv (or a journal) compiles: the manuscript as `restitution.tex` at the top, every
# generated file it reads at the same relative path as in the project (so the source is not
# edited), and the bibliography as typeset (`restitution.bbl`, which LaTeX reads for the job
# `restitution`), not the `.bib`: arXiv runs pdflatex, not bibtex. Nothing outside the bundle is
# referred to. The data tables behind the engine and calibration numbers travel with it. The archive is byte-reproducible: sorted members, the fixed build date, no owners.

# %%
import gzip
import io
import os
import tarfile
from pathlib import Path

from restitution_workflow.atomic import atomic_path
from restitution_workflow.pipeline import start

start(snakemake)
EPOCH = int(os.environ.get("SOURCE_DATE_EPOCH", "1700000000"))

# %% Members: name in the bundle -> file in the project
members = {"restitution.tex": Path(snakemake.input.tex), "restitution.bbl": Path(snakemake.input.bbl),
           # the supplement beside the article, and its .aux where the article's xr reads it
           "supplement.tex": Path(snakemake.input.supplement_tex), "supplement.bbl": Path(snakemake.input.supplement_bbl),
           Path(snakemake.input.supplement_aux).as_posix(): Path(snakemake.input.supplement_aux)}
for path in snakemake.input.generated:
    members[Path(path).as_posix()] = Path(path)
for path in snakemake.input.data:     # data tables at their project paths, read by no TeX run
    members[Path(path).as_posix()] = Path(path)
for name in members:
    # relative, inside the bundle: no absolute path, no way out
    assert not name.startswith("/") and ".." not in Path(name).parts, name

# %% Write it
buffer = io.BytesIO()
with tarfile.TarFile(fileobj=buffer, mode="w", format=tarfile.USTAR_FORMAT) as tar:   # in memory
    for name in sorted(members):
        data = members[name].read_bytes()
        info = tarfile.TarInfo(name)
        info.size, info.mtime, info.mode = len(data), EPOCH, 0o644
        tar.addfile(info, io.BytesIO(data))
with atomic_path(snakemake.output[0]) as tmp, open(tmp, "wb") as raw:
    with gzip.GzipFile(filename="", fileobj=raw, mode="wb", mtime=EPOCH) as gz:
        gz.write(buffer.getvalue())
print(f"{len(members)} files in {snakemake.output[0]}")
