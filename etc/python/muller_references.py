"""The Mueller bed's minimum fluidization velocity: the code's drag law against the correlations.

    references.py [EPS_MF ...]     (default: 0.367, the paper's settled bed of 30 mm; 0.40; 0.43)

At minimum fluidization the gas carries the packed bed's buoyant weight. Per particle at rest in a
homogeneous bed of voidage eps at superficial velocity U (slip u_r = U/eps), Model A's balance (the
particle gets drag and -V grad p; the gas -eps grad p + n f = 0, n V = 1 - eps) is
f = eps (rho_p - rho_g) g V. Solved for U, by bisection, with the code's Di Felice law
(src/openfoam/forceModels/DiFeliceDrag.C: f = pi/8 Cd rho d^2 eps^(2-chi) u_r^2,
Cd = (0.63 + 4.8/sqrt(Re))^2, chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2/2)) with its two Reynolds
numbers: superficial eps u_r d/nu (Di Felice 1994; the tutorial's) and slip u_r d/nu (eq. A7 of Zhang
et al. 2023 as printed). Against:
  - Ergun (1952) at the same voidage: (1 - eps)(rho_p - rho_g) g = 150 (1 - eps)^2 mu U/(eps^3 d^2)
    + 1.75 (1 - eps) rho_g U^2/(eps^3 d);
  - Wen & Yu (1966), no voidage: Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7, Ar = rho_g (rho_p - rho_g)
    g d^3/mu^2.
Particles and gas: Zhang et al. (2023) Table II (1.2 mm, 1000 kg/m3; air 1.2 kg/m3, 1.5e-5 m2/s).
The settled bed: 9240 spheres in 44 x 10 mm; 30 mm high in the paper (§V.B): eps = 0.367.
Writes validation/muller/results/minimumFluidization.csv and prints it.
"""
import math
import os
import sys

from ergun import ergun_gradient
from liquid_bed_references import difelice_cd_chi   # Cd and chi of DiFeliceDrag.C

D, RHO_P, RHO_G, NU, G = 1.2e-3, 1000.0, 1.2, 1.5e-5, 9.81
MU = NU * RHO_G
N, AREA, SETTLED = 9240, 0.044 * 0.010, 0.030
EPS_SETTLED = 1 - N * math.pi / 6 * D ** 3 / (AREA * SETTLED)


def difelice_force(eps, U, superficial=True):
    ur = U / eps
    re = max((eps if superficial else 1.0) * ur * D / NU, 1e-12)
    cd, chi = difelice_cd_chi(re)
    return math.pi / 8 * cd * RHO_G * D ** 2 * eps ** (2 - chi) * ur ** 2


def bisect(f, lo, hi):
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def umf_difelice(eps, superficial=True):
    weight = eps * (RHO_P - RHO_G) * G * math.pi / 6 * D ** 3
    return bisect(lambda U: difelice_force(eps, U, superficial) - weight, 1e-6, 10.0)


def umf_ergun(eps):
    return bisect(lambda U: ergun_gradient(eps, U, D, MU, RHO_G) - (1 - eps) * (RHO_P - RHO_G) * G, 1e-6, 10.0)


def umf_wen_yu():
    ar = RHO_G * (RHO_P - RHO_G) * G * D ** 3 / MU ** 2
    return (math.sqrt(33.7 ** 2 + 0.0408 * ar) - 33.7) * MU / (RHO_G * D)


def main():
    eps_list = [float(a) for a in sys.argv[1:]] or [round(EPS_SETTLED, 3), 0.40, 0.43]
    here = os.path.dirname(os.path.abspath(__file__))
    out = os.path.join(here, "..", "..", "validation", "muller", "results", "minimumFluidization.csv")
    wy = umf_wen_yu()
    rows = []
    for eps in eps_list:
        rows.append((eps, umf_difelice(eps, True), umf_difelice(eps, False), umf_ergun(eps), wy))
    with open(out, "w") as f:
        f.write("# command: validation/muller/references.py " + " ".join(sys.argv[1:]) + "\n")
        f.write("eps_mf,umf_difelice_superficial_m_s,umf_difelice_slip_m_s,umf_ergun_m_s,umf_wen_yu_m_s\n")
        for r in rows:
            f.write(",".join(f"{v:.4g}" for v in r) + "\n")
    print(f"settled bed of 30 mm: eps = {EPS_SETTLED:.3f}; Wen & Yu (no voidage): U_mf = {wy:.3f} m/s")
    print("| eps_mf | Di Felice, superficial Re (code) | Di Felice, slip Re (eq. A7) | Ergun |")
    print("|---|---|---|---|")
    for r in rows:
        print(f"| {r[0]:.3f} | {r[1]:.3f} | {r[2]:.3f} | {r[3]:.3f} |")
    print(f"references.py: wrote {os.path.normpath(out)}")
