/* The geometry table (geometry.h) and what dispatches on it. */
#include "geometry.h"

#include <stddef.h>

static const sbc_frame_geometry *const rows[] = {&sbc_frame_geometry_2d, &sbc_frame_geometry_3d};

const sbc_frame_geometry *sbc_frame_geometry_of(int dim)
{
    size_t k;
    for (k = 0; k < sizeof rows / sizeof rows[0]; ++k)
        if (rows[k]->dim == dim)
            return rows[k];
    return NULL;
}

void sbc_frame_update_geometry(sbc_frame *f) { sbc_frame_geometry_of(f->dim)->area_vectors(f); }

int sbc_frame_family(const sbc_frame *f, int q, int members[8])
{
    return sbc_frame_geometry_of(f->dim)->family(f, q, members);
}

int sbc_frame_faces(const sbc_frame *f, int q) { return sbc_frame_geometry_of(f->dim)->faces(f, q); }
