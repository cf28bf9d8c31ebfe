"""A stage with no rows keeps its heading in the text output, and says why it has none: a deck
whose first run comes before it makes any atom printed "# stage 2 of 2" alone, so a reader counted
one stage where the audit said two."""

import json

from deck_cli import LAMMPS_TWO, needs_lammps, run

LAW = "hertz/material 1e7 {} 0.3 damping viscoelastic tangential linear_nohistory 1 0.3"
#: a run before any atom exists, then two spheres and another law
EARLY_RUN = LAMMPS_TWO.replace("create_atoms 1 single 0.005 0.01 0.03\ncreate_atoms 1 single 0.015 0.01 0.03\n"
                               "set type 1 diameter 0.002 density 2500\n", "") + f"""pair_coeff * * {LAW.format(1e6)}
fix integ all nve/sphere
timestep 1e-5
run 100
create_atoms 1 single 0.005 0.01 0.03
create_atoms 1 single 0.015 0.01 0.03
set type 1 diameter 0.002 density 2500
pair_coeff * * {LAW.format(2e6)}
run 100
"""


@needs_lammps
def test_a_stage_without_rows_has_its_heading_and_says_why(tmp_path):
    assert "create_atoms" not in EARLY_RUN.split("run 100")[0]
    path = tmp_path / "in.deck"
    path.write_text(EARLY_RUN)
    status, out, err = run(path, "--g", "1")
    assert status == 0, err
    lines = out.splitlines()
    first = lines.index("# stage 1 of 2: the contact settings of the run at line 11")
    assert lines[first + 1].startswith("(no rows: the engine holds no atom at this run"), out
    assert lines[first + 2] == "# stage 2 of 2: the contact settings of the run at line 16", out
    status, out, err = run(path, "--g", "1", "--json")
    stages = json.loads(out)["stages"]
    assert [len(s["pairs"]) for s in stages] == [0, 1] and "why" in stages[0] and "why" not in stages[1], stages
