/* Private: the update rules of the servo, a table (GSL's step types): how a
 * servo iteration turns the fixed-gain corrections of servo.c into the
 * frame's next commands. A rule is a row; adding one is a row and its
 * functions. */
#ifndef SBC_UPDATE_RULES_H
#define SBC_UPDATE_RULES_H

#include <stddef.h>

#include "sbc/settings.h"
#include "servo.h"

struct sbc_controller;

/* The secant update's state (controller_update.c): its own, saved with the
 * controller's restart state where 0.2.0 saved it. */
typedef struct sbc_secant {
    double lambda;  /* factor on the fixed-gain corrections */
    int have_prev;  /* d_prev holds this increment's last correction */
    double *d_prev; /* [SBC_CTL_STEP_PARTS(dim) Q] the last fixed-gain correction (du, R dtheta), m */
} sbc_secant;

typedef struct sbc_update_rule {
    sbc_update id;
    const char *name;       /* the value of keyword `update` */
    int scale_free_gains;   /* with kn known, the first steps come from kn (servo.c), not from the
                               per-time-step gains of eq. 37 (Table 4) */
    int bounded;            /* the rule caps its own steps: no stop on a growing residual or on a step
                               over half a radius (controller.c) */
    int keeps_eq15;         /* under (T), the frame is put back on the imposed F after each
                               correction (controller_update.c) */
    /* the correction du, dtheta of the controller scaled as the rule takes it,
       n->max_step with it; NULL: as servo.c computed it. SBC_OK, or a status
       with the message in err (the run stops) */
    sbc_status (*scale)(struct sbc_controller *c, sbc_servo_norms *n, sbc_error *err);
    /* a new increment begins (the rule's state); NULL: nothing to do */
    void (*start)(struct sbc_controller *c);
} sbc_update_rule;

/* The row of a rule; NULL for an id that has none. */
const sbc_update_rule *sbc_update_rule_of(sbc_update id);

/* The row named name (keyword `update`); NULL when there is none. */
const sbc_update_rule *sbc_update_rule_named(const char *name);

/* "fixed, secant or newton": the rules' names, for an error's "expected". */
void sbc_update_rule_names(char *out, size_t cap);

#endif
