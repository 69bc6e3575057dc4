"""Small numerical helpers of the studies: brackets around a step, slopes on logarithmic axes."""
import math


def bracket(values, index):
    """(value at the step before, value at the step) around row `index` of a history column:
    where an event found at that step lies. The value before the first step is 0."""
    return (float(values[index - 1]) if index > 0 else 0.0, float(values[index]))


def middle(pair):
    """The middle of a bracket (low, high)."""
    return 0.5 * (pair[0] + pair[1])


def log_slope(points):
    """Least-squares slope of log y against log x over the points (x, y), all positive: the
    exponent b of a power law y = a x^b. Needs two distinct x."""
    lx = [math.log(x) for x, _ in points]
    ly = [math.log(y) for _, y in points]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return (sum((a - mx) * (b - my) for a, b in zip(lx, ly)) /
            sum((a - mx) ** 2 for a in lx))


def local_slopes(points):
    """d log y / d log x between neighbouring points (x, y) in order of x:
    [(x0, x1, slope)], leaving out pairs of equal x."""
    points = sorted(points)
    return [(a0, a1, math.log(p1 / p0) / math.log(a1 / a0))
            for (a0, p0), (a1, p1) in zip(points, points[1:]) if a1 != a0]
