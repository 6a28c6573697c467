#!/usr/bin/python3
"""Tangential contact-law constant C_t of the 2D disk on a rigid wall.

The disk (radius R, in-plane constants E2, nu2) touches the wall x = 0 at A; a Hertz-shaped
tangential traction of total -T e_y and half-width b acts at A, balanced by the body force
(T/(pi R^2))(1 - 4 xi/R) e_y (xi = x - R, no moment about A).  With u_y(A) the surface
displacement at the centre of the patch (the stick value) and the rigid rotation fixed by a
flat patch (Chebyshev-weighted mean slope of the normal surface displacement over |s| < b,
the step (1 - nu2) T/E2 of the tangential load excluded), the centre of mass moves by
delta_t = <u_y> - u_y(A) = (T/(pi E2)) [2 ln(4R/b) + C_t], C_t = 5/12 - 19 nu2/12 - 2 ln 2,
and the disk turns by <omega> = (T/(pi E2 R)) (1 - 5 nu2)/2; the rotation-free combination
delta_t - R<omega> has the constant C_* = -1/12 + 11 nu2/12 - 2 ln 2.  The finite elements'
rigid rotation, the angular-momentum projection theta_I = int (xi u_y - y u_x) dA / (pi R^4/2),
is R theta_I = (T/(pi E2)) (1 - 8 nu2)/3, and delta_t - R theta_I has the constant
C_I = 1/12 + 13 nu2/12 - 2 ln 2.  (For fields without body force theta_I = <omega> on a disk;
the difference comes from the body force's particular solution.)  The script checks the
closed-form stress and displacement fields by finite differences (equilibrium, free edge,
Hooke's strains; theta_I by quadrature), then recomputes the constants for finite b from an
independent Muskhelishvili series solution of the disk (exact Fourier coefficients of the
Hertz traction, polynomial particular solution for the body force), and repeats the series
computation for the normal problem as a control (C_com = -2 ln 2 - (1 + nu2)/4,
C_diameter = -1).  Also printed: the constants for the d'Alembert body force (translational
plus rigid rotational inertia) in place of the linear one.
"""
import numpy as np
from scipy.special import j0, j1

LN2 = np.log(2.0)


def closed_form(nu, inertial=False):
    """(C_t, R<omega>/K, C_*, R theta_I/K, C_I) in units K = T/(pi E2)."""
    if inertial:
        return (7/4 - nu/4 - 2*LN2, 1.5*(1 - nu), 1/4 + 5*nu/4 - 2*LN2,
                (4 - 5*nu)/3, 5/12 + 17*nu/12 - 2*LN2)
    return (5/12 - 19*nu/12 - 2*LN2, (1 - 5*nu)/2, -1/12 + 11*nu/12 - 2*LN2,
            (1 - 8*nu)/3, 1/12 + 13*nu/12 - 2*LN2)


def fields(X, Y, nu, E=1.0, R=1.0, T=1.0, p=0.0):
    """Closed-form stress, displacement (point load at A) and body force.
    Body force (p y, beta0 - k xi) with k + p = 4T/(pi R^3); p = 0 is the linear one."""
    K, s, m = T/(np.pi*E), T/(2*np.pi*R**3), (1 + nu)/E
    beta0, k = T/(np.pi*R**2), 8*s - p
    c1, c3, sxy0 = 3*s - p/2, s - p/2, -2*s*R**2 + p*R**2/2
    xi, r, th = X - R, np.hypot(X, Y), np.arctan2(Y, X)
    srr = 2*T/np.pi*np.sin(th)/r                                # Flamant, force -T e_y at A
    sxx = srr*np.cos(th)**2 + beta0*Y/2 - 2*s*xi*Y
    syy = srr*np.sin(th)**2 - beta0*Y/2 + 2*s*xi*Y
    sxy = srr*np.sin(th)*np.cos(th) - beta0*xi/2 + c1*xi**2 + c3*Y**2 + sxy0
    c = m*beta0/2
    ux = (-K*((1 - nu)*th + (1 + nu)*np.sin(th)*np.cos(th)) + c*xi*Y
          + m*(-s*xi**2*Y + (2*c3 - s)*Y**3/3 + sxy0*Y))
    uy = (K*(2*np.log(r) + (1 + nu)*np.cos(th)**2) - c/2*(3*xi**2 + Y**2)
          + m*(s*xi*Y**2 + (2*c1 + s)*xi**3/3 + sxy0*xi))
    return (sxx, syy, sxy), (ux, uy), (p*Y, beta0 - k*xi)


def fd_checks(nu, p=0.0, n=2000, h=1e-5, random_state=1):
    rng = np.random.default_rng(random_state)
    rad, phi = np.sqrt(rng.uniform(0, 0.95**2, n)), rng.uniform(0, 2*np.pi, n)
    X, Y = 1 + rad*np.cos(phi), rad*np.sin(phi)
    keep = np.hypot(X, Y) > 0.05
    X, Y = X[keep], Y[keep]
    f = lambda x, y: fields(x, y, nu, p=p)
    (sxx, syy, sxy), _, (bx, by) = f(X, Y)
    d = lambda g, i, j: (f(X + h, Y)[i][j] - f(X - h, Y)[i][j])/(2*h) if g == 'x' else \
                        (f(X, Y + h)[i][j] - f(X, Y - h)[i][j])/(2*h)
    eq = max(np.abs(d('x', 0, 0) + d('y', 0, 2) + bx).max(),
             np.abs(d('x', 0, 2) + d('y', 0, 1) + by).max())
    hooke = max(np.abs(d('x', 1, 0) - (sxx - nu*syy)).max(),
                np.abs(d('y', 1, 1) - (syy - nu*sxx)).max(),
                np.abs(0.5*(d('y', 1, 0) + d('x', 1, 1)) - (1 + nu)*sxy).max())
    ps = rng.uniform(-0.97*np.pi, 0.97*np.pi, 400)             # edge, away from A
    Xe, Ye = 1 - np.cos(ps), np.sin(ps)
    (sxx, syy, sxy), _, _ = f(Xe, Ye)
    nx, ny = Xe - 1, Ye
    edge = max(np.abs(sxx*nx + sxy*ny).max(), np.abs(sxy*nx + syy*ny).max())
    g, w = np.polynomial.legendre.leggauss(200)                 # theta_I: Gauss in polar about A
    th, r = np.pi/2*g[:, None], (1 + g[None, :])*np.cos(np.pi/2*g[:, None])
    X, Y = r*np.cos(th), r*np.sin(th)
    _, (ux, uy), _ = f(X, Y)
    thI = np.pi*np.sum((np.pi/2*w)[:, None]*(w*np.cos(th))*r*((X - 1)*uy - Y*ux))/(np.pi/2)
    thI -= 2 + 3*nu if p == 0 else 1 + 2*nu                     # rigid rotation about A (units K/R)
    return eq, hooke, edge, abs(thI - closed_form(nu, p != 0)[3])


def series(kind, nu, b, inertial=False, N=2**21, E=1.0, T=1.0):
    """Muskhelishvili series for the unit disk (centre 0, A at z = -1, s = pi - theta)."""
    G, kap = E/(2*(1 + nu)), (3 - nu)/(1 + nu)
    k = np.arange(-N, N + 1)
    x = np.abs(k)*b
    J1x = np.where(k == 0, 0.5, j1(x)/np.where(k == 0, 1, x))   # J1(x)/x
    sgn = (-1.0)**np.abs(k)
    th = 2*np.pi*np.arange(16)/16
    xi, y = np.cos(th), np.sin(th)
    if kind == 'tangential':
        tau = -1j*sgn*(T/np.pi)*J1x                             # -f(s) e_y, f Hertz of total T
        M = T*2*j1(b)/b                                         # its moment about the centre
        beta0 = T/np.pi
        kk, pp = (2*M/np.pi, 2*M/np.pi) if inertial else (4*M/np.pi, 0.0)
        # u_p = (-pp y^3/(6G), -beta0 xi^2/(2G) + kk xi^3/(6G)) solves Navier's equation
        sxy = -pp*y**2/2 - beta0*xi + kk*xi**2/2
    else:
        tau = (sgn*(T/np.pi)*J1x).astype(complex)              # +p(s) e_x, Hertz of total T
        rg = T/np.pi
        sxy = rg*y                                              # u_p = (rg y^2/(2G), 0)
    cp = np.fft.fft(-(sxy*y + 1j*sxy*xi))/16                    # -sigma_p n
    for mm in range(-7, 8):
        tau[N + mm] += cp[mm % 16]
    assert abs(tau[N]) < 1e-12 and abs(tau[N + 1].imag) < 1e-12
    F = tau/np.where(k == 0, 1, k)                              # resultant i int tau ds
    F[N] = 0.0
    U = np.where(k >= 2, kap*F, -F)/(2*G)                       # boundary displacement
    U[N + 1] = (kap - 1)*F[N + 1]/2/(2*G)
    U[N] = 0.0
    mean_h = np.conj(F[N + 2])/(2*G)                            # disk mean of u_h
    uA = np.sum(U*sgn)                                          # u_h at A
    K = T/(np.pi*E)
    if kind == 'normal':
        uB = np.sum(U)
        com = (uA.real - mean_h.real - rg/(8*G))/K
        return com - 2*np.log(4/b), (uA.real - uB.real)/K - 2*np.log(4/b)
    uyA = uA.imag - beta0/(2*G) - kk/(6*G)
    uy_mean = mean_h.imag - beta0/(8*G)
    om_mean = (kk + pp)/(16*G)                                  # u_h has no mean rotation
    S = np.sum(U*sgn*(-1j*k)*j0(x)).real - pp*b**2/(4*G)        # Chebyshev mean of du_x/ds
    S += (1 - nu)/E*4*T/(np.pi**2*b)                            # minus the step's ramp
    Om = S/j0(b)                                                # rotation about A: u_x = -Om sin s
    dt, om = uy_mean + Om - uyA, om_mean + Om
    thI = om - (kk + pp)/(48*G)                                 # theta_I = <omega> for u_h
    L = 2*np.log(4/b)
    return dt/K - L, om/K, (dt - om)/K - L, thI/K, (dt - thI)/K - L


if __name__ == '__main__':
    print('closed-form fields, finite differences and quadrature')
    print('(max |residual|, units T/R^2, T/(E R), T/R, K/R):')
    for nu in (0.3, 0.5):
        for p, name in ((0.0, 'linear'), (2/np.pi, "d'Alembert")):
            eq, hk, ed, ti = fd_checks(nu, p)
            print(f'  nu2={nu:.2f} {name:11s} equilibrium {eq:.1e}  Hooke {hk:.1e}'
                  f'  edge traction {ed:.1e}  theta_I {ti:.1e}')
    bs = (0.05, 0.02, 0.01)
    for inertial in (False, True):
        print("\nbody force " + ("d'Alembert (T/(pi R^2)) e_y + (2T/(pi R^3))(y, -xi)" if inertial
                                 else "(T/(pi R^2))(1 - 4 xi/R) e_y"))
        heads = ('C_t', 'R<omega>/K', 'C_*', 'R theta_I/K', 'C_I')
        print(('  nu2     b/R    ' + ''.join(f'{h:13s}' for h in heads)).rstrip())
        for nu in (0.3, 3/7, 0.5):
            rows = [series('tangential', nu, b, inertial) for b in bs]
            ext = [(4*r2 - r1)/3 for r1, r2 in zip(rows[1], rows[2])]   # Richardson in b^2
            labelled = [(f'{b:<5}', r) for b, r in zip(bs, rows)]
            for lab, r in labelled + [('b->0', ext), ('closed', closed_form(nu, inertial))]:
                print(f'  {nu:.4f}  {lab:6s} ' + '    '.join(f'{v:+.6f}' for v in r))
    print('\nnormal control (series, u_x(A) = patch-centre value):')
    print('  nu2     a/R    C_com      closed     C_diameter')
    for nu in (0.3, 0.5):
        for a in bs:
            com, dia = series('normal', nu, a)
            print(f'  {nu:.4f}  {a:<5}  {com:+.6f}  {-2*LN2 - (1 + nu)/4:+.6f}  {dia:+.6f}')
