"""Where Hertz's contact first yields (von Mises), derived independently of
diskimpact: the sphere's axis field (Johnson, Contact Mechanics, 1985,
eq. 3.45) and the half-plane's field on its axis (McEwen 1949), with
sigma_yy = nu (sigma_xx + sigma_zz) in plane strain. The von Mises stress
over p0 is maximized over the depth z/a."""
import math

from scipy.optimize import minimize_scalar


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


def first_yield_pressure_ratio(body, nu):
    """p0/Y at first yield and its depth z/a: body 'sphere' or
    'plane-strain'."""
    field = sphere_axis if body == "sphere" else half_plane_axis
    peak = minimize_scalar(lambda z: -field(z, nu), bounds=(0.05, 2.0),
                           method="bounded", options={"xatol": 1e-10})
    return 1 / field(peak.x, nu), peak.x
