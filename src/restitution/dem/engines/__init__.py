"""The DEM engines, one module (or more) each."""
