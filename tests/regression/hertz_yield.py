"""Where Hertz's contact first yields (von Mises), derived independently of
diskimpact: the sphere's axis field (Johnson, Contact Mechanics, 1985,
eq. 3.45) and the half-plane's field on its axis (McEwen 1949), with
sigma_yy = nu (sigma_xx + sigma_zz) in plane strain; the von Mises stress
over p0 is maximized over the depth z/a. In plane stress (sigma_yy = 0) the
largest von Mises stress lies at the surface, so McEwen's whole field is
searched: a grid over |x| <= 2a, 0 <= z <= 2a, then a local maximization
from its best point."""
import math

from scipy.optimize import minimize, minimize_scalar


def sphere_axis(s, nu):
    sigma_r = -((1 + nu) * (1 - s * math.atan(1 / s)) - 0.5 / (1 + s * s))
    sigma_z = -1 / (1 + s * s)
    return abs(sigma_r - sigma_z)


def half_plane_axis(z, nu):
    m = math.sqrt(1 + z * z)
    sxx = -(m + z * z / m - 2 * z)
    szz = -1 / m
    syy = nu * (sxx + szz)
    return math.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 +
                            (szz - sxx) ** 2))


def half_plane_plane_stress(x, z):
    """von Mises / p0 at (x, z) / a of McEwen's field, sigma_yy = 0."""
    q = 1 - x * x + z * z
    root = math.sqrt(q * q + 4 * x * x * z * z)
    m = math.sqrt(max(0.5 * (root + q), 0.0))
    n = math.copysign(math.sqrt(max(0.5 * (root - q), 0.0)), x)
    if m == 0.0 and n == 0.0:
        return 0.0  # the contact's edge on the surface
    share = (z * z + n * n) / (m * m + n * n)
    sxx = -(m * (1 + share) - 2 * z)
    szz = -m * (1 - share)
    txz = n * (m * m - z * z) / (m * m + n * n)
    return math.sqrt(sxx * sxx + szz * szz - sxx * szz + 3 * txz * txz)


def plane_stress_first_yield():
    """p0/Y at first yield of the plane-stress half-plane, and its depth."""
    grid = [(i / 100, j / 100) for i in range(-200, 201)
            for j in range(0, 201)]
    x0 = max(grid, key=lambda p: half_plane_plane_stress(*p))
    best = minimize(lambda p: -half_plane_plane_stress(p[0], p[1]), x0,
                    bounds=[(-2, 2), (0, 2)], method="L-BFGS-B")
    return 1 / half_plane_plane_stress(*best.x), best.x[1]


def first_yield_pressure_ratio(body, nu):
    """p0/Y at first yield and its depth z/a: body 'sphere', 'plane-strain'
    or 'plane-stress' (which does not depend on nu)."""
    if body == "plane-stress":
        return plane_stress_first_yield()
    field = sphere_axis if body == "sphere" else half_plane_axis
    peak = minimize_scalar(lambda z: -field(z, nu), bounds=(0.05, 2.0),
                           method="bounded", options={"xatol": 1e-10})
    return 1 / field(peak.x, nu), peak.x
