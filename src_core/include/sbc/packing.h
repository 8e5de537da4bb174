/* servo_bc: packings of discs (centres and radii). */
#ifndef SBC_PACKING_H
#define SBC_PACKING_H

#include <stdio.h>

#include "sbc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_packing {
    int n;
    double *x; /* [2n] centres, m */
    double *r; /* [n] radii, m */
    int has_box;    /* 1: a geometrically periodic packing cut to the square `box` */
    double box[4];  /* xlo xhi ylo yhi of that square, m; the frame is the discs crossing its edges */
} sbc_packing;

/* Regular square lattice of Sect. 4.1: nx by ny discs of radius `radius`
 * with centres `spacing` apart, the first at the origin (m). */
sbc_status sbc_packing_lattice_square(sbc_packing *p, int nx, int ny, double spacing, double radius,
                                      sbc_error *err);

/* Reads "x y r" per line (m); '#' starts a comment; errors name the line.
 * An optional line "box XLO XHI YLO YHI" (m) declares a geometrically
 * periodic packing and its square (written by sbc_packing_write_text). */
sbc_status sbc_packing_read(sbc_packing *p, const char *path, sbc_error *err);
/* The same from an open stream; path names it in messages. */
sbc_status sbc_packing_read_stream(sbc_packing *p, FILE *fp, const char *path, sbc_error *err);

/* The most particles a packing may hold (read, lattice): 10 million, where
 * sizes in bytes and neighbour-list indices stay far from overflow. */
#ifndef SBC_PACKING_MAX /* the fuzz builds lower it (Makefile, FUZZ_FLAGS) */
#define SBC_PACKING_MAX 10000000L
#endif

/* Writers, so that every host loads the very same packing (centres and radii
 * printed with 17 significant digits: read back bit for bit):
 *  - text:   "box XLO XHI YLO YHI" when periodic, then "x y r" per line (m);
 *  - lammps: a LAMMPS data file for atom_style sphere, 2D (z = 0, box z
 *            -0.5 0.5 x the largest diameter), atom type 2 for the frame
 *            particles and 1 for the interior, diameter in m and, per atom,
 *            the density 3 rho_A / (4 R) that gives LAMMPS' sphere mass
 *            4/3 pi R^3 rho the disc mass rho_A pi R^2 of eq. 9 (`density`
 *            is rho_A, mass per area, kg/m^2);
 *  - liggghts: the same data file with the density column rho_A, since
 *            LIGGGHTS 3.8 gives 2D spheres M = pi R^2 density;
 *  - yade:   "x y z r frame" per line (m; frame 1 for a frame particle, 0
 *            otherwise): yade.ymport.text reads the first four columns, the
 *            servo_bc YADE module all five. */
sbc_status sbc_packing_write_text(const sbc_packing *p, const char *path, sbc_error *err);
sbc_status sbc_packing_write_lammps(const sbc_packing *p, const int *is_frame, double density, const char *path,
                                    sbc_error *err);
sbc_status sbc_packing_write_liggghts(const sbc_packing *p, const int *is_frame, double density, const char *path,
                                      sbc_error *err);
sbc_status sbc_packing_write_yade(const sbc_packing *p, const int *is_frame, const char *path, sbc_error *err);

/* A sphere packing (centres x [3n], radii r [n], m): the data file of
 * atom_style sphere for host "lammps" or "liggghts" (type 2 = frame, the
 * density column rho, kg/m^3: both give M = 4/3 pi R^3 rho in 3D), and the
 * YADE file (x y z r frame). */
sbc_status sbc_spheres_write_data(int n, const double *x, const double *r, const int *is_frame, double density,
                                  const char *host, const char *path, sbc_error *err);
sbc_status sbc_spheres_write_yade(int n, const double *x, const double *r, const int *is_frame, const char *path,
                                  sbc_error *err);
/* ... and as text, x y z r per line (m); sbc_spheres_read reads such a file
 * (`#` comments) into *x [3n], *r [n], *n (malloc'd; NULL and 0 on failure,
 * with the line and value at fault named as sbc_packing_read does) */
sbc_status sbc_spheres_read(const char *path, int *n, double **x, double **r, sbc_error *err);
sbc_status sbc_spheres_write_text(int n, const double *x, const double *r, const char *path, sbc_error *err);

/* Orientations atan2(dy, dx) (rad) of the branch vectors of all pairs whose
 * gap is below tol (m); *angle is malloc'ed (free it), *count its length. */
sbc_status sbc_packing_contact_angles(const sbc_packing *p, double tol, double **angle, int *count, sbc_error *err);

/* Refuses two of the n discs (centres x [2n], radii r [n], m) whose centres
 * are closer than 1e-6 of the smaller radius: their contact has no normal,
 * and the packing would blow up at the first step. The message names both
 * and their centre. */
sbc_status sbc_packing_distinct(int n, const double *x, const double *r, sbc_error *err);

void sbc_packing_free(sbc_packing *p);

#ifdef __cplusplus
}
#endif

#endif
