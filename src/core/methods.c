/*
 * methods.c -- the one place where kernel methods are registered. To add a method: write
 * methods/<name>.c defining a cdc_method, declare it here and add it to the table.
 */
#include "internal.h"

#include <string.h>

extern const cdc_method cdc_method_centre;
extern const cdc_method cdc_method_divided;
extern const cdc_method cdc_method_big_particle;
extern const cdc_method cdc_method_two_grid;
extern const cdc_method cdc_method_gaussian;
extern const cdc_method cdc_method_exact;

static const cdc_method *const table[] = {&cdc_method_centre,   &cdc_method_divided,  &cdc_method_big_particle,
                                          &cdc_method_two_grid, &cdc_method_gaussian, &cdc_method_exact};
enum { n_methods = sizeof table / sizeof table[0] };

int cdc_method_count(void) { return n_methods; }

const char *cdc_method_name(int i) { return (i >= 0 && i < n_methods) ? table[i]->name : NULL; }

unsigned cdc_method_params(const char *name)
{
    const cdc_method *m = cdc_find_method(name);
    return m ? m->params : 0u;
}

void cdc_method_fill_defaults(const char *name, cdc_kernel_params *prm)
{
    const cdc_method *m = cdc_find_method(name);
    if (m && m->defaults && prm) m->defaults(prm);
}

/* "centre, divided, ...": made from the table, so the messages name exactly the registered methods
 * (per thread, as the core keeps no shared mutable state) */
const char *cdc_method_list(void)
{
    static _Thread_local char list[256];
    if (!list[0])
        for (int i = 0; i < n_methods; ++i) {
            if (i) strncat(list, ", ", sizeof list - strlen(list) - 1);
            strncat(list, table[i]->name, sizeof list - strlen(list) - 1);
        }
    return list;
}

const cdc_method *cdc_find_method(const char *name)
{
    for (int i = 0; name && i < n_methods; ++i)
        if (strcmp(table[i]->name, name) == 0) return table[i];
    return NULL;
}
