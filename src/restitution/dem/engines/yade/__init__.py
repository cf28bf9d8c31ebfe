"""Yade: its contact laws, designer and engine object."""
