"""LAMMPS: its contact law, designer, scene writer and engine object."""
