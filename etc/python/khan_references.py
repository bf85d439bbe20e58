#!/usr/bin/python3
"""khan_references.py -- reference numbers of the binary liquid-fluidized bed (binaryBedKhan),
computed; validation/khan/references.py prints them:

    references.py [-csv FILE] [U ...]     prints them per species (default U = 0.010 0.015 0.020
                                          0.025 m/s); -csv also writes them to FILE

The case: Zhang et al., Phys. Fluids 35, 113330 (2023), §V.C and Table III (after Khan et al.,
Chemeca 2016): 1146 spheres of 1 mm ("big") and 42441 of 0.3 mm ("small"), rho_p = 2000 kg/m3,
water rho_f = 1000 kg/m3, nu = 1e-6 m2/s, g = 9.81 m/s2, a square tube of 10 x 10 mm, 120 mm high.
The paper's text gives the two numbers the other way round; Table III's order is the one that fits
the tube (equal solid volumes, 600 mm3 each).

Per species of diameter d and superficial velocity U:

1. terminal_velocity(d): the paper's own formula (text after its eq. 24, which it takes from Ganguly,
   Int. J. Miner. Process. 29, 235 (1990); the same explicit fit is Khan & Richardson, Chem. Eng.
   Commun. 62, 135 (1987)):  Re_t = (2.33 Ar^0.018 - 1.53 Ar^-0.016)^13.3,
   Ar = (rho_p/rho_f - 1) g d^3 / nu^2,  u_t = Re_t nu / d.
2. alpha_richardson_zaki(U, d): the paper's eq. 24, Richardson & Zaki (Trans. Instn Chem. Engrs
   32, 35 (1954)): U/u_t = (1 - alpha_p)^n, with the exponent of Garside & Al-Dibouni (Ind. Eng.
   Chem. Process Des. Dev. 16, 206 (1977)), (5.1 - n)/(n - 2.7) = 0.1 Re_t^0.9, as the paper does.
   No wall correction (the CFD-DEM has none). This is the paper's Fig. 16 line.
2b. alpha_richardson_zaki_wall(U, d): the same with Richardson & Zaki's (1954) wall correction of
   the velocity the line extrapolates to, u_i = u_t 10^(-d/D) (D: the square tube's width; d/D =
   0.1 for the big species), the Garside-Al-Dibouni exponent kept. Not the acceptance reference:
   what the walls of the experiment's tube would do to it, stated beside the comparison. With
   exponent_wall=True also their exponent's wall term, n = 4.35 + 17.5 (d/D) Re_t^-0.03 (0.2 < Re_t
   < 1), (4.45 + 18 d/D) Re_t^-0.1 (1 < Re_t < 200), 4.45 Re_t^-0.1 (200 < Re_t < 500), 2.39 above,
   4.65 + 19.5 d/D below 0.2 (their whole correlation; printed, a far larger change).
3. alpha_drag_equilibrium(U, d): the homogeneous layer in equilibrium under the code's Di Felice
   drag (src/openfoam/forceModels/DiFeliceDrag.C; Di Felice, Int. J. Multiphase Flow 20, 153
   (1994); Zhang et al. eqs. A4-A7) in Model A: the drag on a particle at rest carries eps times its
   buoyant weight, (3/4) Cd(Re) rho_f U^2 eps^-chi(Re) / d = eps (rho_p - rho_f) g, with the
   superficial Re = alpha_f |u_r| d / nu = U d / nu (the code's default reynoldsNumber superficial).
   Re does not depend on eps, so eps = [3 Cd rho_f U^2 / (4 d (rho_p - rho_f) g)]^(1/(1 + chi)).
   The derivation, and the same equilibrium for the big species alone, are in
   tutorials/liquidFluidizedBed/references.py, whose Cd and chi this script uses.
4. dp_weight(volume): the frictional pressure drop of a fully fluidized bed = its buoyant weight per
   area, (rho_p - rho_f) g V_s / A (momentum balance of the whole column, no correlation).
5. layer_height(alpha, volume) = V_s / (A alpha): a uniform layer's height.
The two layers do not interact in these references: each is the monodisperse bed of its species
(the paper's assumption; Yao, Criddle & Fringer, Phys. Rev. Fluids 6, 084306 (2021) show the
segregated layers behave so, and only the transition region is bidisperse).
"""
import math, sys

# Di Felice's Cd(Re) and chi(Re), and the Garside-Al-Dibouni exponent, as liquidFluidizedBed has them
from liquid_bed_references import difelice_cd_chi, rz_exponent

RHO_P, RHO_F, NU, G = 2000.0, 1000.0, 1e-6, 9.81      # Table III; g
WIDTH, HEIGHT = 0.010, 0.120                          # tube (m)
A = WIDTH * WIDTH
# Table III: name -> (diameter m, number); big below, small above in the steady state
SPECIES = {"big": (1.0e-3, 1146), "small": (0.3e-3, 42441)}
VELOCITIES = (0.010, 0.015, 0.020, 0.025)


def sphere_volume(d):
    return math.pi / 6 * d ** 3


def species_volume(name):
    d, n = SPECIES[name]
    return n * sphere_volume(d)


def archimedes(d):
    return (RHO_P / RHO_F - 1) * G * d ** 3 / NU ** 2


def terminal_velocity(d):
    """(u_t m/s, Re_t) from the paper's Re_t(Ar) (Ganguly 1990 / Khan & Richardson 1987)."""
    ar = archimedes(d)
    re_t = (2.33 * ar ** 0.018 - 1.53 * ar ** -0.016) ** 13.3
    return re_t * NU / d, re_t


def alpha_richardson_zaki(U, d):
    """alpha_p = 1 - (U/u_t)^(1/n); nan when U >= u_t (the species is carried out)."""
    u_t, re_t = terminal_velocity(d)
    return 1 - (U / u_t) ** (1 / rz_exponent(re_t)) if U < u_t else float("nan")


def rz_exponent_wall(re_t, d_over_D):
    """Richardson & Zaki's (1954) exponent with their wall term d/D."""
    if re_t < 0.2:
        return 4.65 + 19.5 * d_over_D
    if re_t < 1:
        return (4.35 + 17.5 * d_over_D) * re_t ** -0.03
    if re_t < 200:
        return (4.45 + 18 * d_over_D) * re_t ** -0.1
    if re_t < 500:
        return 4.45 * re_t ** -0.1
    return 2.39


def alpha_richardson_zaki_wall(U, d, D=WIDTH, exponent_wall=False):
    """alpha_p from Richardson-Zaki with the wall correction of a tube of width D (2b above):
    U/u_i = (1 - alpha_p)^n, u_i = u_t 10^(-d/D); nan when U >= u_i."""
    u_t, re_t = terminal_velocity(d)
    u_i = u_t * 10 ** (-d / D)
    n = rz_exponent_wall(re_t, d / D) if exponent_wall else rz_exponent(re_t)
    return 1 - (U / u_i) ** (1 / n) if U < u_i else float("nan")


def alpha_drag_equilibrium(U, d):
    """alpha_p of the homogeneous layer in equilibrium under the code's Di Felice drag (Model A,
    superficial Re); nan when no voidage below 1 holds the particles (U above their terminal
    velocity under this law)."""
    cd, chi = difelice_cd_chi(U * d / NU)
    eps = (0.75 * cd * RHO_F * U * U / (d * (RHO_P - RHO_F) * G)) ** (1 / (1 + chi))
    return 1 - eps if eps < 1 else float("nan")


def dp_weight(volume):
    """Buoyant weight per tube area (Pa) of a solid volume (m3)."""
    return (RHO_P - RHO_F) * G * volume / A


def layer_height(alpha, volume):
    return volume / (A * alpha)


def rows(velocities):
    """One dict per (U, species): every reference number."""
    out = []
    for U in velocities:
        for name, (d, n) in SPECIES.items():
            u_t, re_t = terminal_velocity(d)
            a_rz, a_df = alpha_richardson_zaki(U, d), alpha_drag_equilibrium(U, d)
            vs = species_volume(name)
            out.append(dict(U=U, species=name, d_mm=1e3 * d, N=n, Ar=archimedes(d), Re_t=re_t, u_t_mm_s=1e3 * u_t,
                            n_rz=rz_exponent(re_t), alpha_rz=a_rz, alpha_rz_wall=alpha_richardson_zaki_wall(U, d),
                            alpha_rz_wall_exponent=alpha_richardson_zaki_wall(U, d, exponent_wall=True),
                            alpha_drag=a_df,
                            H_rz_mm=1e3 * layer_height(a_rz, vs), H_drag_mm=1e3 * layer_height(a_df, vs),
                            dp_species_pa=dp_weight(vs)))
    return out


def main(argv):
    csv_path = None
    if argv[:1] == ["-csv"]:
        if len(argv) < 2:
            print("references.py: -csv needs a file name", file=sys.stderr)
            return 2
        csv_path, argv = argv[1], argv[2:]
    try:
        us = [float(u) for u in argv] or list(VELOCITIES)
    except ValueError:
        print("references.py: velocities must be numbers in m/s, got %s" % " ".join(argv), file=sys.stderr)
        return 2
    total = sum(species_volume(s) for s in SPECIES)
    print("Table III bed: V_s = %.2f mm3 (big %.2f, small %.2f); frictional pressure drop = buoyant weight "
          "per area %.2f Pa (big %.2f, small %.2f)" % (1e9 * total, 1e9 * species_volume("big"),
          1e9 * species_volume("small"), dp_weight(total), dp_weight(species_volume("big")),
          dp_weight(species_volume("small"))))
    rr = rows(us)
    for name in SPECIES:
        r = next(x for x in rr if x["species"] == name)
        print("%-5s d = %.1f mm: Ar = %.1f, Re_t = %.2f, u_t = %.2f mm/s (paper's Re_t(Ar)), n = %.3f "
              "(Garside-Al-Dibouni)" % (name, r["d_mm"], r["Ar"], r["Re_t"], r["u_t_mm_s"], r["n_rz"]))
    for r in rr:
        print("U = %.3f m/s %-5s: alpha_p Richardson-Zaki %.4f (H %.1f mm; wall-corrected u_i %.4f, and their "
              "exponent's wall term %.4f), Di Felice equilibrium %.4f (H %.1f mm)"
              % (r["U"], r["species"], r["alpha_rz"], r["H_rz_mm"], r["alpha_rz_wall"], r["alpha_rz_wall_exponent"],
                 r["alpha_drag"], r["H_drag_mm"]))
    if csv_path:
        keys = list(rr[0].keys())
        with open(csv_path, "w") as f:
            f.write(",".join(keys) + "\n")
            for r in rr:
                f.write(",".join(r[k] if isinstance(r[k], str) else "%.6g" % r[k] for k in keys) + "\n")
    return 0

