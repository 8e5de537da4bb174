#ifndef SBC_TESTS_H
#define SBC_TESTS_H
void test_frame(void);
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
#endif
