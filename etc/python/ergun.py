"""ergun.py -- the Ergun equation (Ergun 1952, Chem. Eng. Prog. 48, 89-94): the frictional pressure
gradient of a fixed bed of spheres of diameter d and voidage eps at superficial velocity U,

    dp/dz = 150 mu (1 - eps)^2 U / (eps^3 d^2) + 1.75 rho (1 - eps) U^2 / (eps^3 d),

the viscous (Blake-Kozeny) and inertial (Burke-Plummer) parts. Used by the fixed-bed tutorials'
checks (ErgunTest, packedBedCylinder) and by the Mueller bed's minimum fluidization velocity
(muller_references.py).
"""


def ergun_gradient(eps, U, d, mu, rho):
    """Frictional pressure drop per unit length (Pa/m)."""
    return (150 * mu * (1 - eps) ** 2 * U / (eps ** 3 * d * d)
            + 1.75 * rho * (1 - eps) * U * U / (eps ** 3 * d))
