# %% [markdown]
# # The arXiv bundle
#
# What arXiv (or a journal) compiles: the manuscript as `restitution.tex` at the top, every
# generated file it reads at the same relative path as in the project (so the source is not
# edited), and the bibliography as typeset (`restitution.bbl`, which LaTeX reads for the job
# `restitution`), not the `.bib`: arXiv runs pdflatex, not bibtex. Nothing outside the bundle is
# referred to. The data tables behind the engine and calibration numbers travel with it, and every
# engine run's deck and output (LAMMPS' behind its figure, each engine's behind the typed-e table),
# with a README.txt at the top saying where they are and how to rerun them. The project's own sources
# travel as an ancillary archive, anc/restitution-sources.tar.gz (arXiv keeps anc/ as downloadable files):
# every file git tracks, with the bytes this build was made from, so a reader can rerun the pipeline. Both
# archives are byte-reproducible: sorted members, the fixed build date, no owners.

# %%
import gzip
import io
import os
import subprocess
import tarfile
import tempfile
from pathlib import Path

from restitution_workflow.atomic import atomic_path
from restitution_workflow.pipeline import start

start(snakemake)
EPOCH = int(os.environ.get("SOURCE_DATE_EPOCH", "1700000000"))
SOURCES = "anc/restitution-sources.tar.gz"


def tar_gz(contents: dict[str, bytes], modes: dict[str, str] | None = None) -> bytes:
    """A gzipped tar of ``contents`` whose bytes depend on the contents alone: sorted members, the fixed
    build date, no owners, mode 644. ``modes`` gives git's mode of a name where it is not a plain file:
    "100755" (mode 755) or "120000" (a symbolic link, whose content is its target)."""
    modes = modes or {}
    buffer = io.BytesIO()
    with tarfile.TarFile(fileobj=buffer, mode="w", format=tarfile.USTAR_FORMAT) as tar:   # in memory
        for name in sorted(contents):
            data = contents[name]
            info = tarfile.TarInfo(name)
            info.mtime = EPOCH
            if modes.get(name) == "120000":
                # the field rounds' decks hold links (to files, folders, loops): kept as links, so that the
                # unpacked tree is the commit's
                info.type, info.linkname, info.mode = tarfile.SYMTYPE, data.decode(), 0o777
                tar.addfile(info)
                continue
            info.size = len(data)
            info.mode = 0o755 if modes.get(name) == "100755" else 0o644
            tar.addfile(info, io.BytesIO(data))
    raw = io.BytesIO()
    with gzip.GzipFile(filename="", fileobj=raw, mode="wb", mtime=EPOCH) as gz:
        gz.write(buffer.getvalue())
    return raw.getvalue()


def tracked_sources() -> tuple[dict[str, bytes], dict[str, str]] | None:
    """Every file git tracks in this checkout, as it is on disk (at a clean commit: the commit's bytes),
    under restitution-sources/, with git's mode of each; a link's content is its target. None where this
    is not a git checkout (a copy made without .git)."""
    listed = subprocess.run(["git", "ls-files", "-s", "-z"], capture_output=True)
    if listed.returncode != 0:
        return None
    contents, modes = {}, {}
    for entry in listed.stdout.decode().split("\0"):
        if not entry:
            continue
        meta, path = entry.split("\t", 1)
        name = f"restitution-sources/{path}"
        modes[name] = meta.split()[0]
        if modes[name] == "120000":
            contents[name] = os.readlink(path).encode()
        elif Path(path).is_file():
            contents[name] = Path(path).read_bytes()
        else:   # deleted in an uncommitted change: not part of what was built
            del modes[name]
    return contents, modes


def git_tree(files: dict[str, bytes], modes: dict[str, str]) -> str:
    """The git tree hash of ``files`` (names under restitution-sources/), found as a reader finds it from
    the unpacked archive (``git init``, ``git add -A -f``, ``git write-tree``), so that the hash the README
    states is the one their check prints; it equals ``git rev-parse COMMIT^{tree}`` of a clean build."""
    with tempfile.TemporaryDirectory() as tmp_dir:        # a scratch copy, no output of the rule
        root = Path(tmp_dir) / "restitution-sources"
        for name, data in files.items():
            tmp_file = Path(tmp_dir) / name
            tmp_file.parent.mkdir(parents=True, exist_ok=True)
            if modes[name] == "120000":
                os.symlink(data.decode(), tmp_file)
                continue
            tmp_file.write_bytes(data)
            tmp_file.chmod(0o755 if modes[name] == "100755" else 0o644)
        # no user or system git settings (autocrlf, filters) may change what is hashed
        env = {**os.environ, "GIT_CONFIG_GLOBAL": os.devnull, "GIT_CONFIG_NOSYSTEM": "1"}
        for command in (["init", "-q"], ["add", "-A", "-f"]):
            subprocess.run(["git", *command], cwd=root, env=env, check=True, capture_output=True)
        return subprocess.run(["git", "write-tree"], cwd=root, env=env, check=True, capture_output=True,
                              text=True).stdout.strip()


def commit_tree() -> str | None:
    """The tree of the checkout's HEAD, or None where git cannot say."""
    head = subprocess.run(["git", "rev-parse", "HEAD^{tree}"], capture_output=True, text=True)
    return head.stdout.strip() if head.returncode == 0 else None


# %% Members: name in the bundle -> file in the project
members = {"restitution.tex": Path(snakemake.input.tex), "restitution.bbl": Path(snakemake.input.bbl),
           # the supplement beside the article, its .aux where the article's xr reads it, and the numbers of the
           # article's labels where the supplement's xr reads them
           "supplement.tex": Path(snakemake.input.supplement_tex), "supplement.bbl": Path(snakemake.input.supplement_bbl),
           Path(snakemake.input.supplement_aux).as_posix(): Path(snakemake.input.supplement_aux),
           Path(snakemake.input.article_labels).as_posix(): Path(snakemake.input.article_labels)}
for path in snakemake.input.generated:
    members[Path(path).as_posix()] = Path(path)
for path in [*snakemake.input.data, *snakemake.input.engine_runs, *snakemake.input.typed_e_runs,
             snakemake.input.manifest]:
    members[Path(path).as_posix()] = Path(path)   # at their project paths, read by no TeX run
runs_readme = Path(snakemake.input.engine_runs[-1]).as_posix()
claims = next(Path(p).as_posix() for p in snakemake.input.data if p.endswith("/claims.csv"))
accuracy = next(Path(p).as_posix() for p in snakemake.input.data if p.endswith("/reference/accuracy.csv"))
typed_readme = Path(snakemake.input.typed_e_runs[-1]).as_posix()
readme = f"""\
restitution.tex and supplement.tex compile with pdflatex alone, run until the log asks for no rerun
(the bibliographies are the .bbl files; the article reads the supplement's labels from the .aux it carries,
the supplement the numbers of the article's labels from results/paper/article_labels.aux).
The tables behind the engine and calibration numbers are under results/dem/ and results/paper/ (CSV);
the ledger of Kim's claims, with each row's tolerance and notes, is {claims}.
Every LAMMPS run behind the article's LAMMPS figure is under {Path(runs_readme).parent.as_posix()}/: one deck (.in) and its
screen output (.out) per run; {runs_readme} says how to rerun one and how each eps is read from it.
Every engine run behind the typed-e table (LAMMPS, LIGGGHTS, Yade, Kratos: each row in the engine named
for it) is under {Path(typed_readme).parent.as_posix()}/, with the eps each run gave beside the table's;
{typed_readme} says how to rerun them.
{snakemake.input.manifest} lists every one of those run files with its SHA-256 checksum and size.

{{sources}}

Where the pieces are in the project's sources (the archive under anc/): each figure and table
of the supplement is made by one script under workflow/scripts/, a step of the Snakemake pipeline
(rules in workflow/rules/, settings in config.yaml), which records its inputs.
  series coefficients table: series_table.py, from series.py
  forward and inverse collision figures, damped-only phase portrait: fig1_forward.py, fig2_inverse.py,
    fig3_phase.py
  readings of Kim's procedure and their errors in eps: connection_readings.py, eps_compare.py
  ledger of Kim's claims: claims.py
  uniform approximation (both end rules), its error figure and table: uniform_section.py (also the limits'
    constants)
  eps against Omega for every force law, validation table: compare_variants.py, validation.py,
    variants_tex.py; the other force laws' sections: variant_section.py, with the main figures' scripts
  speed against accuracy (table and figure): bench_section.py, from one recorded run of `make bench`
    kept under benchmarks/recorded/
  Feng's calibration: feng_calibration.py
  half-power series of Hertz's law and its truncation errors: schwager_poeschel.py
  stability atlas (table and figure): stability_atlas.py, fig_stability.py (library
    restitution.audit.stability; its grid, tolerances and parallel jobs are the defaults of
    restitution.audit.stability.AtlasSpec, which an optional stability block of config.yaml overrides,
    field by field, as workflow/schemas/config.schema.yaml describes)
  uniform-approximation atlas: uniform_atlas.py
The tolerance study (the supplement's accuracy of the reference integrations) is {accuracy}. Kim's matching procedure, in all its
readings, is restitution.audit.matching; the reading used for the figures is set in config.yaml, which
also lists the force laws (as "variants"). `restitution eps --method uniform --json` prints the
uniform approximation's numbers (its old name closed-form still works, with a note). The DEM codes' contact laws are restitution.dem.engines, one module per code;
`restitution calibrate` (with --end for the end rule) inverts eps(Omega), and `restitution lammps --eps`
writes the pair_coeff line. The overlap rule's constant C is computed by restitution.core.overlap_limit,
and 1 - eps from the dissipated energy by restitution.core.energy.
"""
for name in members:
    # relative, inside the bundle: no absolute path, no way out
    assert not name.startswith("/") and ".." not in Path(name).parts, name

# %% The sources, as an ancillary archive
contents = {name: path.read_bytes() for name, path in members.items()}
sources = tracked_sources()
if sources is None:
    note = ("This bundle was made from a copy of the project that is not a git checkout, so it does not carry\n"
            "the sources (a bundle made in the git checkout has them under anc/).")
else:
    files, modes = sources
    contents[SOURCES] = tar_gz(files, modes)
    tree = git_tree(files, modes)
    same = ("the tree of that commit" if tree == commit_tree() else
            "NOT the tree of that commit: the build was made with uncommitted changes")
    note = (f"{SOURCES} holds the project's sources: the {len(files)} files under version control, as built\n"
            f"(commit {snakemake.params.commit}). Unpacked, `make paper` in restitution-sources/ rebuilds both\n"
            "documents, every number included; its README.md says what the build needs.\n"
            f"Its files' git tree hash is {tree}, {same} (in the project's repository:\n"
            "git rev-parse COMMIT^{tree}). To recompute it: tar xzf the archive, then in restitution-sources/\n"
            "git init -q && git add -A -f && git write-tree.")
contents["README.txt"] = readme.replace("{sources}", note).encode()

# %% Write it
with atomic_path(snakemake.output[0]) as tmp:
    Path(tmp).write_bytes(tar_gz(contents))
print(f"{len(contents)} files in {snakemake.output[0]}")
