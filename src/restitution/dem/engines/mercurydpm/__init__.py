"""MercuryDPM: its contact law (from its documentation) and engine object."""
