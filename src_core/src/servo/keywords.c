/* servo_bc: the keyword registry (keywords.h). */
#include "sbc/keywords.h"

#include <stdio.h>
#include <string.h>

const sbc_keyword sbc_keywords[SBC_KEYWORDS] = {
    {"F",
     "F11 F12 F21 F22",
     "final macroscopic deformation gradient (full F̄, not F̄ − I); F̄ ramps linearly from I over the "
         "increments; det F̄ > 0; nine values F11 … F33, row-major, on a 3D packing",
     "I"},
    {"increments",
     "N ≥ 1",
     "loading increments i_tot; increment 0 relaxes the packing at F̄ = I; with mixed, the increments of "
         "the deformation stage (i_tot − i_vs), after the stress stage",
     "1"},
    {"accuracy",
     "`fast`, `balanced`, `tight`, `paper`",
     "a preset: the relaxation criterion and its tolerance, `tol_relative`, `update`, `speed` and "
         "`damping`; `fast`, `balanced`, `tight` guarantee every row's equilibrium residual (force balance "
         "1e-3, 1e-5, 1e-8), and so the stress to 1e-2, 1e-4, 1e-6 where the path has one equilibrium; on a "
         "frictional packing they do not fix the path (measured per increment size in \"Interior\"); `paper` "
         "is Table 4 as printed and guarantees nothing (see \"Accuracy\"); keywords given with it win "
         "wherever they stand",
     "balanced"},
    {"balance",
     "tol window",
     "relaxed when the largest net force on an interior particle is ≤ tol times the mean contact force and "
         "Ek ≤ tol²/2 · Ep, for `window` consecutive steps (see \"Accuracy\"); 0 < tol ≤ 1",
     "preset (1e-5 20)"},
    {"relax",
     "tolE window",
     "instead of `balance`: the paper's criterion, Ek/Ep ≤ tolE for `window` consecutive steps after a "
         "kinetic-energy maximum (eqs. 11–12, see below)",
     "(`paper`: 1e-3 20)"},
    {"speed",
     "v ≥ 0",
     "the frame travels to new positions (a new increment, a servo correction) along a straight line at no "
         "more than v radii per critical time step √(2M_q/kn) of each frame particle; 0 = in one time step, as "
         "the paper",
     "preset (0.01)"},
    {"max_relax_steps",
     "N",
     "a relaxation longer than N steps stops the run with an error naming the increment, the iteration and "
         "the criterion's measures",
     "1e7"},
    {"damping",
     "`fire`, α β, or `none`",
     "what dissipates the interior's energy: `fire`, FIRE's velocity mix (see \"Accuracy\"); α β, the "
         "local non-viscous damping of eq. 10, 0 ≤ α, β < 1; with `fire`, β = 0.7 still damps the free frame "
         "rotations of (T)",
     "preset (`fire`; `paper`: 0.7 0.7)"},
    {"gain_force gain_moment gain_deformation",
     "g > 0",
     "dimensionless servo gains g·M/Δt², g·M·R²/Δt², g·R² (Table 4); used by (P), (T) with `update fixed` "
         "(the secant update of the presets takes its first step from the host's kn instead)",
     "1e2, 2e2, 2e-5"},
    {"tol_force tol_moment tol_deformation",
     "ε > 0",
     "servo residual tolerances of eq. 37 (Table 4); used by (P), (T); `tol_force` or `tol_moment` given "
         "without `tol_relative` sets `tol_relative 0`",
     "1e-6, 1e-6, 1e-2"},
    {"predict",
     "n_f in [0, 1]",
     "inheritance factor of the displacement prediction; 0 = none; used by (P), (T)",
     "0"},
    {"stress",
     "Pij value N",
     "mixed only: first Piola–Kirchhoff component P̄ij (N/m; N/m² in 3D) held by the (T) components whose "
         "edge or face normal is e_j, ramped linearly over a stress stage of N increments (i_vs); several "
         "components share one stage; N = 0 holds it from increment 0 (a prestressed packing is not "
         "unloaded first) without a stage or a new reference",
     "–"},
    {"bottom right top left",
     "Mx My, each D, P or T",
     "mixed only, 2D: how the x and y displacement of that edge's particles are controlled (see \"Mixed\")",
     "D D, P P, D T, P P"},
    {"xlo xhi ylo yhi zlo zhi",
     "Mx My Mz, each D, P or T",
     "mixed only, 3D: how the x, y and z displacement of that face's particles are controlled (see \"Mixed\")",
     "P P P on xlo xhi ylo yhi, D D D on zlo, D D T on zhi"},
    {"update",
     "`fixed`, `secant` or `newton`",
     "`fixed`: the corrections of eqs. 33, 34, 36, 48 with the gains as given; `secant`: corrections with "
         "scale-free first steps (1/(4 kn) per ± pair, 1/(2 kn) per particle, 1/(4 kn R²) per rotation) scaled "
         "by a Barzilai–Borwein factor learned from the last two iterations, at most 0.002 R per correction; "
         "`newton` ((P), (T); the embedded runner and the material point): the correction that balances the "
         "frame on the linearized contact network with the interior condensed out, scaled by the same factor "
         "from 1, at most 0.05 R (see \"Newton\"); "
         "under (T), each correction is followed by restoring eq. 15 exactly (see below)",
     "preset (secant)"},
    {"tol_relative",
     "ε ≥ 0",
     "> 0: converge on the force and moment residuals relative to the frame's own forces, "
         "√(Σ\\|Δa\\|²/Σ\\|a_q\\|²) and √(Σ Δm²/Σ (\\|a_q\\| R_q)²), instead of `tol_force`, `tol_moment`; the "
         "CSV's `r_force`, `r_moment` are then these",
     "preset (1e-4)"},
    {"max_iterations",
     "K ≥ 1",
     "servo iterations per increment before a divergence error",
     "100000"},
    {"seal",
     "`yes` or `no`",
     "the edges of the polygon of the frame's centres become frictionless walls that no disc passes (see "
         "\"Seal\"; in 3D the triangles of the surface through them, [frame3d.md](frame3d.md) \"Seal\"); for "
         "irregular packings sheared far enough that a disc would slip out between frame discs",
     "no"},
    {"rotation",
     "`free` or `zero`",
     "T only: `free` is the paper's (T), the frame's rotations free; `zero` holds them at zero as (D) does, the "
         "alternative that carries load on irregular sphere packings, where frame spheres with fewer than three "
         "contacts roll ([frame3d.md](frame3d.md) \"(T) and the frame's rotations\")",
     "free"},
    {"remap",
     "`x` or `none`",
     "`x`: while the frame travels to an increment's first positions, every interior particle follows the "
         "affine part of the change of F̄ (as `fix deform … remap x` in LAMMPS), so that the relaxation starts "
         "near its answer instead of from a wave at the frame (see \"Remap\"); the host must move its "
         "interior (every engine here does)",
     "x; none with `accuracy paper` and in a material point"},
    {"interior",
     "`dynamic` or `newton`",
     "how the interior reaches each new position of the frame: `dynamic`, relaxation by the host's dynamics "
         "with damping; `newton` (embedded runner, discs (with cohesive bonds too) and spheres; D, P, T, mixed): the static equilibrium at the "
         "frame's commands, the contact laws integrated over the increment by backward Euler and solved by Newton on "
         "the contact network's stiffness, then certified as every row (see \"Interior\"); the frame jumps "
         "to its commands (`speed 0`, `remap none`); hosts refuse it",
     "dynamic"},
    {"frame",
     "group-ID",
     "boundary particles given by a host group; the embedded runner detects the frame itself and refuses "
         "this keyword",
     "detected"},
    {"file",
     "path",
     "CSV, one row per converged increment, flushed at once",
     "none"},
    {"tangent",
     "`affine`, `condensed` or `perturbation`, then a path",
     "the embedded runner's: the tangent C̄ = ∂P̄/∂F̄ at every converged increment into a CSV, "
         "`increment,C1111,C1112,…` (dim⁴ columns, C_ijkl with (ij), (kl) row-major); D, P, T on discs "
         "or spheres (with cohesive bonds condensed or perturbation; see [fe2.md](fe2.md)); hosts refuse it",
     "none"},
};

/* the name-th word of a row's names into out [cap]; 0 past the last */
static int name_at(const sbc_keyword *k, int name, char *out, size_t cap)
{
    const char *p = k->names;
    int i;
    for (i = 0; i < name; ++i) {
        p = strchr(p, ' ');
        if (!p)
            return 0;
        ++p;
    }
    snprintf(out, cap, "%.*s", (int)strcspn(p, " "), p);
    return 1;
}

int sbc_keywords_list(char *out, size_t cap)
{
    char name[64];
    size_t used = 0;
    int k, i, total = 0, at = 0;
    for (k = 0; k < SBC_KEYWORDS; ++k)
        for (i = 0; name_at(&sbc_keywords[k], i, name, sizeof name); ++i)
            ++total;
    for (k = 0; k < SBC_KEYWORDS; ++k)
        for (i = 0; name_at(&sbc_keywords[k], i, name, sizeof name); ++i, ++at) {
            const char *sep = at == 0 ? "" : at == total - 1 ? " or " : ", ";
            if (used < cap)
                snprintf(out + used, cap - used, "%s%s", sep, name);
            used += strlen(sep) + strlen(name);
        }
    return (int)used;
}
