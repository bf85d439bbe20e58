"""standard_drag.py -- the standard drag curve of a single rigid sphere and the terminal velocity it
gives; the single-sphere (alpha = 1) form of each drag law of src/openfoam/forceModels.

Reference: Clift, R., Grace, J. R. & Weber, M. E. (1978), Bubbles, Drops, and Particles, Academic
Press, Table 5.2 ("recommended drag correlations", w = log10 Re), the ranges used here:

    Re <= 0.01          Cd = 3/16 + 24/Re
    0.01 < Re <= 20     Cd = 24/Re (1 + 0.1315 Re^(0.82 - 0.05 w))
    20 < Re <= 260      Cd = 24/Re (1 + 0.1935 Re^0.6305)
    260 < Re <= 1500    log10 Cd = 1.6435 - 1.1242 w + 0.1558 w^2
    1500 < Re <= 1.2e4  log10 Cd = -2.4571 + 2.5558 w - 0.9295 w^2 + 0.1049 w^3

Accuracy taken for it: +-5 % in Cd (README.md of this tutorial: Clift et al. list Schiller-Naumann as
within +5/-4 % of this curve for Re < 800, Table 5.1; Brown & Lawler's independent fit to 480
wall-corrected points, J. Environ. Eng. 129 (2003) 222, eq. 19,
    Cd = 24/Re (1 + 0.150 Re^0.681) + 0.407 / (1 + 8710/Re),
differs from Table 5.2 by at most 5 % over 0.1 <= Re <= 1500; cd_spread() prints it).

Terminal velocity: Cd(Re) Re^2 = (4/3) Ar, Ar = g (rho_p/rho_f - 1) d^3 / nu^2, Re = u_t d / nu.
A relative error eps in Cd moves u_t by -eps / (2 - m), m = -dln Cd/dln Re (Stokes m = 1: eps;
Newton m = 0: eps/2).
"""
import math

G = 9.81
CD_ACCURACY = 0.05          # relative, in Cd (see above)


def cd_clift(Re):
    """Clift, Grace & Weber (1978) Table 5.2, for Re <= 1.2e4."""
    if Re <= 0:
        raise ValueError("Re must be positive")
    w = math.log10(Re)
    if Re <= 0.01:
        return 3.0 / 16 + 24.0 / Re
    if Re <= 20:
        return 24.0 / Re * (1 + 0.1315 * Re ** (0.82 - 0.05 * w))
    if Re <= 260:
        return 24.0 / Re * (1 + 0.1935 * Re ** 0.6305)
    if Re <= 1500:
        return 10 ** (1.6435 - 1.1242 * w + 0.1558 * w * w)
    if Re <= 1.2e4:
        return 10 ** (-2.4571 + 2.5558 * w - 0.9295 * w * w + 0.1049 * w ** 3)
    raise ValueError("Re > 1.2e4 is beyond the part of Table 5.2 used here")


def cd_brown_lawler(Re):
    """Brown & Lawler (2003), eq. 19, Re < 2e5: the cross-check of the reference's accuracy."""
    return 24.0 / Re * (1 + 0.150 * Re ** 0.681) + 0.407 / (1 + 8710.0 / Re)


# the drag laws of src/openfoam/forceModels for one sphere in unbounded fluid (alpha = 1)
def cd_schiller_naumann(Re):
    return 24.0 / Re * (1 + 0.15 * Re ** 0.687) if Re < 1000 else 0.44


def cd_dallavalle(Re):
    """Di Felice's single-particle Cd (Dallavalle 1948), DiFeliceDrag at alpha = 1."""
    return (0.63 + 4.8 / math.sqrt(Re)) ** 2


def cd_koch_hill(Re):
    """KochHillDrag at phi = 0: F = F0 + F3 Re/2 with F0 = 1, F3 = 0.0673 + 0.0232."""
    return 24.0 / Re * (1 + 0.5 * (0.0673 + 0.0232) * Re)


LAW_CD = {
    "DiFeliceDrag": cd_dallavalle,
    "GidaspowDrag": cd_schiller_naumann,        # Wen-Yu branch at alpha = 1
    "SchillerNaumannDrag": cd_schiller_naumann,
    "KochHillDrag": cd_koch_hill,
}

# where each law claims validity, as a single sphere (alpha = 1); the force models warn outside it
LAW_RANGE = {
    "DiFeliceDrag": ("1e-2 < Re < 1e4 (Di Felice 1994's data)", lambda Re: 1e-2 < Re < 1e4),
    "GidaspowDrag": ("Re < 800 (its Schiller-Naumann Cd; Clift et al. 1978 Table 5.1)", lambda Re: Re < 800),
    "SchillerNaumannDrag": ("Re < 800 (Clift et al. 1978 Table 5.1)", lambda Re: Re < 800),
    "KochHillDrag": ("phi >= 0.01 (Hill, Koch & Ladd 2001; Benyahia et al. 2006): never for one sphere",
                     lambda Re: False),
}


def archimedes(d, rho_p, rho_f, nu):
    return G * (rho_p / rho_f - 1) * d ** 3 / nu ** 2


def terminal_re(cd, Ar):
    """Re_t solving cd(Re) Re^2 = 4/3 Ar (cd Re^2 increases with Re), by bisection in log Re."""
    lo, hi = 1e-8, 1.2e4
    target = 4.0 / 3 * Ar
    if cd(hi) * hi * hi < target:
        raise ValueError("terminal Re above 1.2e4")
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        if cd(mid) * mid * mid > target:
            hi = mid
        else:
            lo = mid
    return math.sqrt(lo * hi)


def terminal_velocity(cd, d, rho_p, rho_f, nu):
    Re = terminal_re(cd, archimedes(d, rho_p, rho_f, nu))
    return Re * nu / d, Re


def velocity_tolerance(Re, cd_eps=CD_ACCURACY):
    """Relative u_t band from a relative Cd band at Re: eps / (2 - m), m = -dln Cd/dln Re."""
    h = 1e-3
    m = -(math.log(cd_clift(Re * (1 + h))) - math.log(cd_clift(Re * (1 - h)))) / \
        (math.log(1 + h) - math.log(1 - h))
    return cd_eps / (2 - m)


def cd_spread(res=(0.1, 0.3, 1, 3, 10, 30, 100, 300, 1000, 1500)):
    """Brown & Lawler vs Clift et al. and each law vs Clift et al., relative, in Cd."""
    rows = []
    for Re in res:
        ref = cd_clift(Re)
        rows.append((Re, cd_brown_lawler(Re) / ref - 1,
                     {law: f(Re) / ref - 1 for law, f in LAW_CD.items()}))
    return rows


if __name__ == "__main__":
    print("Re      Brown-Lawler  " + "  ".join(f"{k:>19s}" for k in LAW_CD))
    for Re, bl, laws in cd_spread():
        print(f"{Re:<7g} {100*bl:+11.1f} %  " + "  ".join(f"{100*v:+17.1f} %" for v in laws.values()))
