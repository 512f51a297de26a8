#!/usr/bin/env python3
"""Writes cylinder.1, cylinder.3 and cylinder.hst: WAMIT-format coefficients of a
vertical circular cylinder (radius R, draft T, WAMIT's ULEN = 1) from closed
forms (README.md). Nondimensional as WAMIT writes them: A/rho, B/(rho omega),
X/(rho g), C/(rho g)."""
import math

R, T = 5.0, 50.0
G = 9.80665
S = math.pi * R * R        # water-plane area
V = S * T                  # displaced volume
B0, SIGMA = 2.0e5, 1.0     # surge/sway damping B(w) = B0 exp(-w^2 / (2 SIGMA^2)) [N s/m]
RHO = 1025.0

def added_mass():
    a = [[0.0] * 6 for _ in range(6)]
    a[0][0] = a[1][1] = S * T              # slender strips, Ca = 1
    a[0][4] = a[4][0] = -S * T * T / 2     # surge-pitch about the SWL origin
    a[1][3] = a[3][1] = S * T * T / 2      # sway-roll
    a[3][3] = a[4][4] = S * T ** 3 / 3
    a[2][2] = 2.0 / 3.0 * R ** 3           # heave: a chosen value, no closed form used
    return a

def rows(m):
    return [(i, j, m[i][j]) for i in range(6) for j in range(6) if m[i][j] != 0.0]

omegas = [0.05 * k for k in range(1, 81)]   # 0.05 .. 4 rad/s
with open("cylinder.1", "w") as f:
    for per in (-1.0, 0.0):
        for i, j, v in rows(added_mass()):
            f.write(f"{per:14.6E} {i+1:5d} {j+1:5d} {v:14.6E}\n")
    for w in omegas:
        per = 2 * math.pi / w
        b = B0 * math.exp(-w * w / (2 * SIGMA ** 2))
        for i, j, v in rows(added_mass()):
            damp = b / (RHO * w) if (i, j) in ((0, 0), (1, 1)) else 0.0
            f.write(f"{per:14.6E} {i+1:5d} {j+1:5d} {v:14.6E} {damp:14.6E}\n")

def excitation(w, beta):
    # Long-wave Morison forces per unit amplitude (deep water, Cm = 2), over rho g:
    k = w * w / G
    decay = math.exp(-k * T)
    fx = 2 * S * (1 - decay)                            # i * (rho g) * this, in the wave's direction
    my = 2 * S * ((decay * (1 + k * T) - 1) / k)        # i * (rho g) * this: int z k e^{kz} dz * 2 S
    fz = S * decay                                      # Froude-Krylov on the bottom, in phase
    c, s = math.cos(beta), math.sin(beta)
    return [1j * fx * c, 1j * fx * s, fz + 0j, -1j * my * s, 1j * my * c, 0j]

with open("cylinder.3", "w") as f:
    for w in omegas:
        per = 2 * math.pi / w
        for beta_deg in (-180.0, -90.0, 0.0, 90.0, 180.0):
            x = excitation(w, math.radians(beta_deg))
            for i in range(6):
                if x[i] == 0:
                    continue
                mod, ph = abs(x[i]), math.degrees(math.atan2(x[i].imag, x[i].real))
                f.write(f"{per:14.6E} {beta_deg:10.2f} {i+1:5d} {mod:14.6E} {ph:10.3f} "
                        f"{x[i].real:14.6E} {x[i].imag:14.6E}\n")

with open("cylinder.hst", "w") as f:
    c = [[0.0] * 6 for _ in range(6)]
    c[2][2] = S
    c[3][3] = c[4][4] = V * (-T / 2) + math.pi * R ** 4 / 4
    for i in range(6):
        for j in range(6):
            f.write(f"{i+1:5d} {j+1:5d} {c[i][j]:14.6E}\n")
