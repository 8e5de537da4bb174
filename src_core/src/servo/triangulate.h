/* Private: the Delaunay triangulation of points in the unit square whose
 * hull is the square itself (triangulate.c), as the 3D periodic frame's faces
 * need it (frame_3d_periodic.c). */
#ifndef SBC_TRIANGULATE_H
#define SBC_TRIANGULATE_H

/* Triangulates the m points uv [2m] of the unit square [0, 1]^2: the four
 * corners must be among them, every other point lies either exactly on a
 * side (a coordinate exactly 0 or 1) or strictly inside. Writes the
 * triangles into tri [3 (2m - 5)] as point indices, anticlockwise in (u, v),
 * and returns their count, 2m - h - 2 with h the points on the sides; every
 * stretch of a side between two consecutive points on it is the edge of
 * exactly one triangle. Returns -1 when the input breaks these rules (a
 * corner missing, a point outside or twice) or the floating-point
 * predicates left a triangulation that does not tile the square (checked:
 * positive areas summing to 1). Bowyer-Watson, O(m^2). */
int sbc_triangulate_square(int m, const double *uv, int *tri);

#endif
