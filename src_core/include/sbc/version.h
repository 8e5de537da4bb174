/* servo_bc: the version of this library (CHANGELOG.md), printed by the
 * runner (servo-bc --version), the LAMMPS and LIGGGHTS fixes' log and the
 * YADE module (servo_bc.__version__). */
#ifndef SBC_VERSION_H
#define SBC_VERSION_H

#ifdef __cplusplus
extern "C" {
#endif

#define SBC_VERSION "0.3.0"

/* SBC_VERSION as the library was built, for hosts that load it at run time. */
const char *sbc_version(void);

#ifdef __cplusplus
}
#endif

#endif
