#ifndef SBC_TESTS_H
#define SBC_TESTS_H
void test_frame(void);
void test_frame_3d(void);
void test_frame_3d_periodic(void);
void test_irregular_3d(void);
void test_spheres(void);
void test_homogenize(void);
void test_contact(void);
void test_cohesive(void);
void test_bonds(void);
void test_bonds_runner(void);
void test_rattler_energy(void);
void test_relax(void);
void test_lattice(void);
void test_input(void);
void test_outputs(void);
void test_servo(void);
void test_restart(void);
void test_generate(void);
void test_mixed(void);
void test_host(void);
void test_decks(void);
void test_bpm(void);
void test_accuracy(void);
void test_seal(void);
void test_seal_3d(void);
void test_point(void);
void test_condensed(void);
void test_newton(void);
void test_interior(void);
void test_interior_spheres(void);
void test_interior_bonds(void);
void test_bpm_host(void);
void test_cohesive_host(void);
void test_driver(void);
void test_remap(void);

struct sbc_frame;
/* the largest |sum_q X_q (x) A_q - V I| of a 3D frame over V (test_frame3d.c) */
double test_frame_identity_error(const struct sbc_frame *f);
#endif
