"""The staged exact predicates of dtlab (kernel/predicates.hpp), vectorised over arrays of points.

Each argument is an ``(n, 2)`` / ``(n, 3)`` float array, or one point ``(2,)`` / ``(3,)`` used for
every row; the result is an ``int8`` array of signs (``-1``, ``0``, ``1``), or a Python ``int``
when every argument is a single point.

``stage`` chooses what runs:

* ``"filtered"`` (default): the staged predicate, semi-static filter first, then the dynamic
  filter, the exact expansion and GMP as needed; always decides; counted in :func:`stats`.
* ``"semi_static"``, ``"dynamic"``, ``"expansion"``: that stage alone; where it cannot certify the
  sign the entry is :data:`UNDECIDED` (``2``). Not counted.
* ``"exact"``: the GMP oracle; always decides. Not counted.

Sign conventions: ``orient2d(a, b, c) > 0`` iff a, b, c turn counter-clockwise;
``incircle(a, b, c, d) > 0`` iff d is inside the circle through a, b, c (counter-clockwise);
``orient3d(a, b, c, d) > 0`` iff ``det(b - a, c - a, d - a) > 0``; ``insphere(a, b, c, d, e) > 0``
iff e is inside the sphere through a, b, c, d (with ``orient3d(a, b, c, d) > 0``).
``perturbed=True`` (incircle / insphere, filtered stage) resolves an exact zero by the symbolic
perturbation every dtlab triangulation uses.
"""

from ._dtlab import predicates as _p

UNDECIDED = _p.UNDECIDED
orient2d = _p.orient2d
incircle = _p.incircle
orient3d = _p.orient3d
insphere = _p.insphere


def stats():
    """This thread's counts since it started or since :func:`reset_stats`: for each predicate,
    how many calls each stage decided (``semistatic``, ``adaptive`` (the dynamic filter),
    ``exact``), of those how many needed the symbolic perturbation (``perturbed``) or GMP
    (``gmp``), and ``calls``. Counts every filtered call, those made inside dtlab's algorithms on
    this thread included."""
    return _p.stats()


def reset_stats():
    """Zeroes this thread's counters."""
    _p.reset_stats()


__all__ = ["UNDECIDED", "orient2d", "incircle", "orient3d", "insphere", "stats", "reset_stats"]
