"""The paper audit: what Kim's paper prints, its matching procedure, the claims ledger and the
stability atlas; builds on :mod:`restitution.core` (and reads the pipeline's outputs).

printed (the paper's numbers), readings and matching (the paper's procedure for c0-c2 as the
text allows it to be read), relations (the paper's c's as rungs of the fast ladder), claims
(the ledger), stability (the atlas of exponents x Omega).
"""
