"""Helpers every workflow script imports: `pipeline` (logging, deterministic output, notebook
replay), `atomic` (the one atomic writer, with the record of what was written), `latex`
(numbers and text as the manuscript prints them). Nothing here does physics."""
