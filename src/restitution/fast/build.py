"""What a build of the method ladder is: something a rung reads that is made once, cached on disk
and checked when loaded (a master curve, a uniform form, a relation's c0-c2, a check against
mpmath), as :mod:`restitution.fast.rung` says what a rung is.

A build (:class:`Build`) declares, for one :class:`Site` (the exponents, the calibration settings,
what the ladder has loaded so far):

* ``name``: what a rung's ``needs`` gives to ask for it;
* ``after``: the builds it reads (made and loaded before it);
* ``key(site)``: its cache entry's name, which changes whenever what it holds would;
* ``make(site)``: the dict that is stored (the seconds-long part);
* ``valid(site, d)``: whether a stored dict may be used (an unreadable one is not: it is rebuilt);
* ``load(site, d)``: what the rungs read, from the stored dict;
* ``what(site)``: the words that name it on stderr;
* ``seconds`` and ``price(site)``: what it is expected to take, by kind of exponents, until this
  process has timed one (MEASURED_SECONDS).

The registry is :mod:`restitution.fast.builds`; the chooser (:mod:`restitution.fast.ladder`)
looks builds up there by name and knows none of them.
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Mapping

from ..core.exponents import Exponents
from .master import MasterSettings

__all__ = ["Build", "Site", "MEASURED_SECONDS", "digest", "safe_name"]

#: What builds took in this process, by (build, kind, settings): the latest one prices the next.
MEASURED_SECONDS: dict = {}


def digest(text: str) -> str:
    """The first 12 hex digits of the sha256 of ``text`` (a settings key inside a cache key).

    Parameters
    ----------
    text : str
        Any text; its UTF-8 bytes are hashed.

    Returns
    -------
    str
        Twelve hex digits.

    Examples
    --------
    >>> digest("")
    'e3b0c44298fc'
    """
    return hashlib.sha256(text.encode()).hexdigest()[:12]


def safe_name(name: str) -> str:
    """``name`` with every character but letters, digits and "-" turned into "_" (for a file name).

    Parameters
    ----------
    name : str
        A rung's or relation's name.

    Returns
    -------
    str
        The name as a cache key may hold it.

    Examples
    --------
    >>> safe_name("paper c0/c2")
    'paper_c0_c2'
    """
    return "".join(c if c.isalnum() or c == "-" else "_" for c in name)


@dataclass(frozen=True)
class Site:
    """What one ladder makes its builds for: the exponents, the calibration settings, where
    progress is said, and what it has loaded so far by build name (a live view: the builds a
    build reads, its ``after``, are there when it is made or loaded).

    Parameters
    ----------
    ex : Exponents
        The exponents.
    settings : MasterSettings
        The calibration settings (the master curve's, with its mpmath check's point count).
    progress : callable, optional
        Called with one line of progress while a long build runs.
    built : mapping, optional
        The loaded builds, by name.

    Examples
    --------
    >>> from restitution.core.exponents import as_exponents
    >>> site = Site(as_exponents("3/2", "1"), MasterSettings())
    >>> site.pair, site.kind
    ('a3/2-g1', 'alpha>gamma')
    """

    ex: Exponents
    settings: MasterSettings
    progress: Callable[[str], None] = lambda msg: None
    built: Mapping[str, Any] = field(default_factory=dict)

    @property
    def kind(self) -> str:
        """"alpha>gamma" or "alpha<=gamma": builds differ in cost by orders of magnitude between them."""
        return "alpha>gamma" if self.ex.alpha > self.ex.gamma else "alpha<=gamma"

    @property
    def pair(self) -> str:
        """The exponents as cache keys spell them."""
        return f"a{self.ex.alpha}-g{self.ex.gamma}"

    @property
    def for_pair(self) -> str:
        """The exponents as stderr spells them."""
        return f"alpha={self.ex.alpha}, gamma={self.ex.gamma}"

    @property
    def master_settings(self) -> MasterSettings:
        """The master curve's own settings: its mpmath check is a build of its own."""
        return replace(self.settings, n_highprec=0)


class Build:
    """Base of every build (see the module docstring); subclasses set ``name`` and ``seconds`` and
    define ``key``, ``make``, ``valid``, ``load`` and ``what``.

    Examples
    --------
    >>> from restitution.core.exponents import as_exponents
    >>> class Table(Build):
    ...     name, seconds = "table", {"alpha>gamma": 0.5}
    >>> site = Site(as_exponents("3/2", "1"), MasterSettings(), built={})
    >>> Table().price(site), Table().price(Site(as_exponents("1", "1"), MasterSettings()))
    (0.5, inf)
    """

    name: str = ""
    #: The builds it reads, by name.
    after: tuple[str, ...] = ()
    #: Seconds it took on the 2-core machine when idle (about twice that when busy), by kind
    #: (Site.kind): its price until this process has timed one of that kind (inf: not priced).
    seconds: Mapping[str, float] = {}

    def key(self, site: Site) -> str:
        raise NotImplementedError

    def make(self, site: Site) -> dict:
        raise NotImplementedError

    def valid(self, site: Site, d: dict) -> bool:
        raise NotImplementedError

    def load(self, site: Site, d: dict) -> object:
        return d

    def what(self, site: Site) -> str:
        return f"the {self.name} for {site.for_pair}"

    def measured_key(self, site: Site) -> tuple:
        """Where MEASURED_SECONDS keeps what this build took for ``site``."""
        return self.name, site.kind, site.settings.key()

    def price(self, site: Site) -> float:
        """Expected seconds to make it for ``site``: what the last one took in this process, else
        ``seconds``."""
        measured = MEASURED_SECONDS.get(self.measured_key(site))
        return measured if measured is not None else self.seconds.get(site.kind, math.inf)

    def timed(self, site: Site, seconds: float) -> None:
        """Record that making it for ``site`` took ``seconds`` (what prices the next one)."""
        MEASURED_SECONDS[self.measured_key(site)] = seconds
