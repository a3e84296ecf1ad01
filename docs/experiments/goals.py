"""The battery's counts for the experiment scripts (core/src/battery/goals.rs is the source):
each row is (the pipeline's NE_psi, the best other method's, raw integration's)."""


def lines(best):
    """The within and worse-than-2x lines of a case whose best other method has `best`:
    1.25x + 0.05 and 2x + 0.05 (deg/min)."""
    return 1.25 * best + 0.05, 2 * best + 0.05


def counts(rows, raw_margin=1.1):
    """Within 1.25x + 0.05 of the best other, worse than 2x + 0.05, worse than raw by more
    than `raw_margin` (the battery's 10 %; the format probe counts any amount, 1.0), and the
    largest ratio to the best other."""
    within = sum(p <= lines(b)[0] for p, b, _ in rows)
    over = sum(p > lines(b)[1] for p, b, _ in rows)
    raw = sum(p > raw_margin * r for p, _, r in rows)
    worst = max(p / b for p, b, _ in rows)
    return within, over, raw, worst
