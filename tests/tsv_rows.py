"""Rows of the tests' tab-separated tables (a table of cases kept beside the test that reads it)."""

from __future__ import annotations

from pathlib import Path


def tsv_rows(path: Path, columns: int) -> list[list[str]]:
    """Each row of ``path`` split at its tabs: blank lines and lines starting with # are comments;
    a row with another number of columns is an error naming its line."""
    rows = []
    for n, line in enumerate(Path(path).read_text().splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        cells = line.split("\t")
        if len(cells) != columns:
            raise ValueError(f"{path}:{n}: {len(cells)} columns, not {columns}")
        rows.append(cells)
    return rows
