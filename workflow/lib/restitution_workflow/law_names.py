"""The physical name a document prints for a variant of config.yaml, in place of its file label.

The labels (``kim``, ``hertz``, ``dashpot``) name folders and rules; a reader needs the force law.
A variant not listed here (a one-off study) keeps its label.
"""

from __future__ import annotations

#: label -> name of the force law, as LaTeX text
LAW_NAMES = {
    "kim": "Kim's exponents",
    "hertz": "Hertz--Kuwabara--Kono",
    "dashpot": "linear dashpot",
}


def law_name(label: str, *, tex: bool = True) -> str:
    """The force law's name for a variant label, as LaTeX (``tex``) or plain text (figure legends).

    Parameters
    ----------
    label : str
        The variant's name in config.yaml.
    tex : bool, optional
        LaTeX text (en dash as ``--``) if true, else plain text with a Unicode en dash.

    Returns
    -------
    str
        The name; a label not listed is returned unchanged (escaped by the caller where needed).

    Examples
    --------
    >>> law_name("hertz"), law_name("hertz", tex=False), law_name("flat")
    ('Hertz--Kuwabara--Kono', 'Hertz–Kuwabara–Kono', 'flat')
    """
    name = LAW_NAMES.get(label, label)
    return name if tex else name.replace("--", "\u2013")
