#define LAMMPS_VERSION "29 Sep 2021"
#define LAMMPS_UPDATE "Update 2"
