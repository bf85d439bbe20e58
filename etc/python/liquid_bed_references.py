#!/usr/bin/python3
"""liquid_bed_references.py -- the reference numbers of tutorials/liquidFluidizedBed, computed (no
tabulated values); that tutorial's references.py prints them:

    references.py [U ...]      prints them (default U = 0.015 0.020 0.025 m/s) and writes
                               results/references.csv

Case (Zhang et al., Phys. Fluids 35, 113330 (2023) §V.C and Table III, big species; Khan et al.
2016): N = 1146 spheres, d = 1 mm, rho_p = 2000 kg/m3, water rho_f = 1000 kg/m3, nu = 1e-6 m2/s,
g = 9.81 m/s2, tube cross-section A = 10 x 10 mm.

1. eps_drag_equilibrium(U, law): the homogeneous-bed equilibrium of the code's drag law `law`
   (DiFelice, the tutorial's default; Gidaspow; KochHill: Allrun -drag). Every law gives a force
   f = K(eps, Re) u_r on a particle at rest, with the interstitial slip u_r = U/eps and the
   superficial Reynolds number Re = eps |u_r| d/nu = U d/nu (the form of each law below is the
   one in src/openfoam/forceModels/<law>Drag.C, written again here from its header):
   - DiFelice (Di Felice, Int. J. Multiphase Flow 20, 153 (1994); Zhang et al. eqs. A4-A7):
       f = pi/8 Cd rho_f d^2 eps^(2-chi) u_r^2 = pi/8 Cd rho_f d^2 U^2 eps^(-chi),
       Cd = (0.63 + 4.8/sqrt(Re))^2, chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2/2);
   - Gidaspow (Gidaspow 1994; Ergun below eps = 0.8, Wen & Yu above):
       eps <= 0.8: K = V (150 (1 - eps) mu/(eps d^2) + 1.75 rho_f u_r/d),
       eps >  0.8: K = V 0.75 Cd rho_f eps u_r/d eps^-2.65, Cd = 24/Re (1 + 0.15 Re^0.687);
   - KochHill (Hill, Koch & Ladd, J. Fluid Mech. 448 (2001), in the form of Benyahia et al.,
     Powder Technol. 162 (2006)): K = V 18 mu eps^2 (F0(phi) + F3(phi) Re/2)/d^2, phi = 1 - eps,
       F0 = (1 + 3 sqrt(phi/2) + 135/64 phi ln phi + 16.14 phi)/(1 + 0.681 phi - 8.48 phi^2
            + 8.16 phi^3) for phi < 0.4, 10 phi/(1 - phi)^3 above; F3 = 0.0673 + 0.212 phi
            + 0.0232/(1 - phi)^5.
   Model A (the particle gets drag + gradPForce -V grad p; the fluid -eps grad p + eps rho_f g -
   n f = 0 with n V = 1 - eps): f (1 + (1 - eps)/eps) = (rho_p - rho_f) V g, so
       f = eps (rho_p - rho_f) g pi d^3/6.
   Model B without gradPForce (drag / eps, plus Archimedes rho_f V g): f/eps = (rho_p - rho_f) V g,
   the same equation. Solved for eps by bisection on (0.2, 1).
2. eps_richardson_zaki(U): Richardson & Zaki (Trans. Instn Chem. Engrs 32, 35 (1954)),
   eps = (U/u_t)^(1/n), with
   - the terminal velocity of Khan & Richardson (Chem. Eng. Commun. 62, 135 (1987); Zhang et al.'s
     formula, which it attributes to Ganguly 1990): Re_t = (2.33 Ar^0.018 - 1.53 Ar^-0.016)^13.3,
     Ar = (rho_p/rho_f - 1) g d^3/nu^2, u_t = Re_t nu/d;
   - the exponent of Garside & Al-Dibouni (Ind. Eng. Chem. Process Des. Dev. 16, 206 (1977)):
     (5.1 - n)/(n - 2.7) = 0.1 Re_t^0.9.
   No wall correction (the CFD-DEM has none either).
3. dp_weight: the buoyant weight of the bed per area, (rho_p - rho_f) g V_s / A with
   V_s = N pi d^3/6: the frictional pressure drop of a fully fluidized bed (momentum balance of
   the whole column, no correlation).
4. H(eps) = V_s / (A (1 - eps)): the height of a homogeneous bed of voidage eps.
"""
import math, os, sys

N, D, RHO_P, RHO_F, NU, G = 1146, 1e-3, 2000.0, 1000.0, 1e-6, 9.81
PERSIST_FROZEN = 0.5   # share of contacts lasting 0.1 s from which a bed counts as frozen (short mode)
A = 0.010 * 0.010
VP = math.pi / 6 * D ** 3               # one particle's volume
VS = N * VP


def difelice_cd_chi(re):
    """Cd and chi of DiFeliceDrag.C for the particle Reynolds number re."""
    cd = (0.63 + 4.8 / math.sqrt(re)) ** 2
    chi = 3.7 - 0.65 * math.exp(-(1.5 - math.log10(re)) ** 2 / 2)
    return cd, chi


DRAG_LAWS = ("DiFelice", "Gidaspow", "KochHill")


def drag_force(law, eps, U, d=D):
    """Drag (N) on a particle of diameter d (default the tutorial's 1 mm) at rest in a homogeneous
    bed of voidage eps at superficial velocity U."""
    re, ur, mu, vol = U * d / NU, U / eps, NU * RHO_F, math.pi / 6 * d ** 3
    if law == "DiFelice":
        cd, chi = difelice_cd_chi(re)
        return math.pi / 8 * cd * RHO_F * d ** 2 * U ** 2 * eps ** (-chi)
    if law == "Gidaspow":
        if eps <= 0.8:
            k = vol * (150 * (1 - eps) * mu / (eps * d ** 2) + 1.75 * RHO_F * ur / d)
        else:
            cd_re = 24 * (1 + 0.15 * re ** 0.687) if re < 1000 else 0.44 * re
            k = vol * 0.75 * cd_re * NU / (eps * d) * RHO_F * eps / d * eps ** -2.65
        return k * ur
    if law == "KochHill":
        phi = 1 - eps
        if phi < 0.4:
            f0 = ((1 + 3 * math.sqrt(phi / 2) + (135 / 64 * phi * math.log(phi) if phi > 0 else 0) + 16.14 * phi)
                  / (1 + 0.681 * phi - 8.48 * phi ** 2 + 8.16 * phi ** 3))
        else:
            f0 = 10 * phi / (1 - phi) ** 3
        f3 = 0.0673 + 0.212 * phi + 0.0232 / (1 - phi) ** 5
        return vol * 18 * mu * eps ** 2 * (f0 + 0.5 * f3 * re) / d ** 2 * ur
    raise ValueError("unknown drag law %r (%s)" % (law, " ".join(DRAG_LAWS)))


def eps_drag_equilibrium(U, law="DiFelice", d=D):
    """Voidage where the code's drag law on a particle (diameter d) at rest equals eps (rho_p - rho_f) V g."""
    def residual(eps):                    # drag per particle / (eps x buoyant weight) - 1
        return drag_force(law, eps, U, d) / (eps * (RHO_P - RHO_F) * G * math.pi / 6 * d ** 3) - 1

    lo, hi = 0.2, 1.0                     # residual(lo) > 0 (too much drag), residual(hi) < 0
    if not (residual(lo) > 0 > residual(hi)):
        return float("nan")              # U beyond the fluidized range: no root in (0.2, 1)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if residual(mid) > 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def terminal_velocity(d=D):
    """u_t (m/s) and Re_t of Khan & Richardson (1987)."""
    ar = (RHO_P / RHO_F - 1) * G * d ** 3 / NU ** 2
    re_t = (2.33 * ar ** 0.018 - 1.53 * ar ** -0.016) ** 13.3
    return re_t * NU / d, re_t, ar


def rz_exponent(re_t):
    """n of Garside & Al-Dibouni (1977): (5.1 - n)/(n - 2.7) = 0.1 Re_t^0.9."""
    a = 0.1 * re_t ** 0.9
    return (5.1 + 2.7 * a) / (1 + a)


def eps_richardson_zaki(U, d=D):
    u_t, re_t, _ = terminal_velocity(d)
    return (U / u_t) ** (1 / rz_exponent(re_t))


def dp_weight():
    """Buoyant weight of the bed per cross-section (Pa)."""
    return (RHO_P - RHO_F) * G * VS / A


def height(eps):
    return VS / (A * (1 - eps))


def main(out):
    """print the numbers at the velocities on the command line and write them as CSV into out"""
    us = [float(u) for u in sys.argv[1:]] or [0.015, 0.020, 0.025]
    u_t, re_t, ar = terminal_velocity()
    print("Ar = %.1f, Re_t = %.2f, u_t = %.2f mm/s, n = %.3f (Garside-Al-Dibouni), "
          "V_s = %.2f mm3, dp_weight = %.2f Pa" % (ar, re_t, 1e3 * u_t, rz_exponent(re_t), 1e9 * VS, dp_weight()))
    rows = ["U,Re,eps_drag_equilibrium,eps_richardson_zaki,H_drag_equilibrium_mm,H_richardson_zaki_mm,dp_weight"]
    for U in us:
        ed, er = eps_drag_equilibrium(U), eps_richardson_zaki(U)
        print("U = %.3f m/s (Re = %.0f): eps drag equilibrium %.3f (H %.2f mm), Richardson-Zaki %.3f (H %.2f mm)"
              % (U, U * D / NU, ed, 1e3 * height(ed), er, 1e3 * height(er)))
        rows.append("%g,%.4g,%.5f,%.5f,%.4f,%.4f,%.4f" % (U, U * D / NU, ed, er, 1e3 * height(ed), 1e3 * height(er), dp_weight()))
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w") as f:
        f.write("\n".join(rows) + "\n")

