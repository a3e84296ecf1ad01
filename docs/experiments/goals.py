"""The battery's counts for the experiment scripts (core/src/battery/goals.rs is the source):
each row is (the pipeline's NE_psi, the best other method's, raw integration's)."""


def counts(rows, raw_margin=1.1):
    """Within 1.25x + 0.05 of the best other, worse than 2x + 0.05, worse than raw by more
    than `raw_margin` (the battery's 10 %; the format probe counts any amount, 1.0), and the
    largest ratio to the best other."""
    within = sum(p <= 1.25 * b + 0.05 for p, b, _ in rows)
    over = sum(p > 2 * b + 0.05 for p, b, _ in rows)
    raw = sum(p > raw_margin * r for p, _, r in rows)
    worst = max(p / b for p, b, _ in rows)
    return within, over, raw, worst
