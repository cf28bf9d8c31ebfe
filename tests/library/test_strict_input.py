"""Input the README does not document is refused, not quietly read as something else: on the
command line " 3/2 ", "-0", "1_000", "1_0/4" (Python reads 5/2) and an option given twice (the
last used to win); in the API a complex Omega (its imaginary part dropped), True as a speed (1),
a string as a number, build="no" (truthy: it built)."""

from __future__ import annotations

import io

import numpy as np
import pytest

from restitution import epsilon
from restitution.cli import main
from restitution.core.collision import collide
from restitution.core.errors import ParameterError
from restitution.core.model import Material


@pytest.mark.parametrize("argv, field", [
    (["eps", "--alpha", "3/2", "--gamma", "-0", "--omega", "1"], "gamma = '-0'"),
    (["eps", "--alpha", " 3/2 ", "--gamma", "1", "--omega", "1"], "alpha = ' 3/2 '"),
    (["eps", "--alpha", "1_0/4", "--gamma", "1", "--omega", "1"], "alpha = '1_0/4'"),
    (["collide", "--alpha", "3/2", "--gamma", "1 ", "--omega", "1"], "gamma = '1 '"),
    (["eps", "--alpha", "3/2", "--gamma", "1", "--omega", "1_000"], "--omega"),
    (["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0x10"], "--omega"),
    (["eps", "--alpha", "3/2", "--gamma", "1", "--omega", "1", "--omega", "2"], "--omega given twice"),
    (["collide", "--alpha", "3/2", "--alpha", "1", "--gamma", "1", "--omega", "1"], "--alpha given twice"),
    (["eps", "--alpha", "3/2", "--gamma", "1", "--omega=1", "--omega=2"], "--omega given twice"),
])
def test_the_cli_takes_only_what_the_readme_documents(argv, field, capsys):
    assert main(argv, io.StringIO()) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and field in err[0], err


@pytest.mark.parametrize("flag, item", [
    ("--radius", "1=abc"), ("--density", "1="), ("--radius", "1=0.001=2"), ("--density", "2=nan"),
])
def test_a_deck_type_value_that_is_no_number_is_one_line_exit_2(tmp_path, capsys, flag, item):
    """These ended in an argparse.ArgumentTypeError traceback, exit status 1."""
    deck = tmp_path / "in.deck"
    deck.write_text("units si\n")
    assert main(["deck", str(deck), "--g", "1", flag, item], io.StringIO()) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{flag.lstrip('-')} = '{item}'" in err[0] and "Traceback" not in err[0], err


def test_documented_forms_still_work(capsys):
    out = io.StringIO()
    assert main(["eps", "--alpha", "1.5", "--gamma", "1", "--omega", "5e-1", "2.5E+0", "--no-build"], out) == 0
    assert main(["collide", "--alpha", "3/2", "--gamma", "0", "--omega", ".5"], io.StringIO()) == 0


@pytest.mark.parametrize("call, field", [
    (lambda: epsilon(alpha="3/2", gamma=1, omega=0.5 + 1j), "omega"),
    (lambda: epsilon(alpha="3/2", gamma=1, omega=[0.5, 2j]), "omega"),
    (lambda: epsilon(alpha="3/2", gamma=1, omega=np.array([0.5 + 0j])), "omega"),
    (lambda: epsilon(alpha="3/2", gamma=1, g=True, D1=0.000296, D2=0.0109), "g"),
    (lambda: epsilon(alpha="3/2", gamma=1, g=[0.1, True], D1=0.000296, D2=0.0109), "g"),
    (lambda: epsilon(alpha="3/2", gamma=1, omega="0.5"), "omega"),
    (lambda: epsilon(alpha="3/2", gamma=1, omega=0.5, build="no"), "build"),
    (lambda: epsilon(alpha="3/2", gamma=1, omega=0.5, build=1), "build"),
    (lambda: collide(("3/2", 1), 0.5 + 1j), "omega"),
    (lambda: collide(("3/2", 1), True), "omega"),
    (lambda: collide(("3/2", 1), "0.5"), "omega"),
    (lambda: Material(alpha="3/2", gamma=1, D1=0.000296, D2=0.0109).omega(np.array([True])), "g"),
])
def test_the_api_takes_the_same_rules(call, field):
    with pytest.raises(ParameterError) as err:
        call()
    assert str(err.value).startswith(f"{field} =")


def test_numpy_numbers_are_numbers():
    assert epsilon(alpha="3/2", gamma=1, omega=np.float32(0.5), build=False).eps.shape == ()
    assert collide(("3/2", 1), np.float64(0.5)).eps == pytest.approx(0.3437503260, rel=1e-9)
    assert Material(alpha="3/2", gamma=1, D1=0.000296, D2=0.0109).omega(np.array([0.1, 1])).shape == (2,)
