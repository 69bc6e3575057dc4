"""The closed form of the inflated thick sphere, for the peer benchmark (bench/peer-shell and
shell_inflation.py): plain Python, no DOLFINx.

Units: mm, MPa.

An incompressible neo-Hookean sphere (W = c1 (I1 - 3), shear modulus mu = 2 c1) of inner radius
RI and outer radius RO in the reference state, inflated by a pressure p on its inner surface.
With a the deformed inner radius, incompressibility gives the outer one, b^3 = a^3 + RO^3 - RI^3,
and with la = a / RI, lb = b / RO the radial equilibrium integrates to
    p(a) = 2 mu (1/lb - 1/la + 1/(4 lb^4) - 1/(4 la^4)).
p(a) rises to a limit p_max and falls beyond it; for RI = 10, RO = 11 mm and c1 = 0.0033 MPa,
p_max = 7.789e-4 MPa at a = 14.26 mm.
"""
import math

RI, RO = 10.0, 11.0  # [mm]


def pressure(a, c1, ri=RI, ro=RO):
    """p(a) [MPa] at deformed inner radius a [mm] > 0; c1 [MPa]."""
    mu = 2.0 * c1
    b = (a**3 + ro**3 - ri**3) ** (1.0 / 3.0)
    la, lb = a / ri, b / ro
    return 2.0 * mu * (1.0 / lb - 1.0 / la + 0.25 / lb**4 - 0.25 / la**4)


def limit_pressure(c1, ri=RI, ro=RO):
    """(p_max [MPa], a [mm] where p(a) = p_max): the maximum of p over a in (ri, 2 ri), found by
    golden-section search (p has one maximum there) to 1e-10 mm in a."""
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    low, high = ri, 2.0 * ri
    while high - low > 1e-10:
        left, right = high - ratio * (high - low), low + ratio * (high - low)
        if pressure(left, c1, ri, ro) < pressure(right, c1, ri, ro):
            low = left
        else:
            high = right
    a = 0.5 * (low + high)
    return pressure(a, c1, ri, ro), a
