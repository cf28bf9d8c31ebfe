"""Kratos Multiphysics DEMApplication: its contact laws, designer, runner, material files and engine object."""
