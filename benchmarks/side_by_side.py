"""Median seconds of several calls timed side by side (what the array benchmarks share): each call
once first (builds made, kernels compiled), then ``repeats`` rounds in which the calls take turns, so
that a drift of a shared machine's speed falls on all of them alike."""

from __future__ import annotations

import statistics
import time


def medians(calls: dict, repeats: int) -> dict:
    """{name: median seconds} of the callables in ``calls``, warm, taking turns."""
    return {name: statistics.median(t) for name, t in timings(calls, repeats).items()}


def timings(calls: dict, repeats: int) -> dict:
    """{name: list of seconds} of the callables in ``calls``, warm, taking turns."""
    for call in calls.values():
        call()
    times: dict = {name: [] for name in calls}
    for _ in range(repeats):
        for name, call in calls.items():
            start = time.perf_counter()
            call()
            times[name].append(time.perf_counter() - start)
    return times
