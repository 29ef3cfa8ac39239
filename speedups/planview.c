/* <planView>: its geometries (line, arc, spiral, poly3, paramPoly3) in order of s. */
#include <string.h>

#include "read.h"

static const char *const HEAD[] = {"s", "x", "y", "hdg", "length"};
static const char *const POLY3[] = {"a", "b", "c", "d"};
static const char *const PARAM_POLY3[] = {"aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV"};

/* Read count numbers named names into args (stopping at the first FALLBACK or error); 1 if all were read. */
static int numbers_into(const xmlNode *node, const char *const *names, int count, const Reading *r, PyObject **args)
{
    for (int i = 0; i < count; i++) {
        args[i] = number(node, names[i], r, 0);
        if (args[i] == NULL) {
            return 0;
        }
    }
    return 1;
}

static PyObject *geometry(const xmlNode *node, const Reading *r, double *s_out)
{
    const xmlNode *shape = NULL;
    for (const xmlNode *child = node->children; child != NULL; child = child->next) {
        if (named(child, "line") || named(child, "arc") || named(child, "spiral") || named(child, "poly3") ||
            named(child, "paramPoly3")) {
            if (shape != NULL) {
                return FALLBACK; /* two shapes: a finding */
            }
            shape = child;
        }
    }
    if (shape == NULL) {
        return FALLBACK;
    }
    PyObject *args[15] = {NULL};
    Py_ssize_t n = 5;
    PyObject *constructor;
    int ok = numbers_into(node, HEAD, 5, r, args);
    if (ok && (PyFloat_AS_DOUBLE(args[0]) < 0.0 || PyFloat_AS_DOUBLE(args[4]) < 0.0)) {
        ok = 0;
    }
    const char *kind = (const char *)shape->name;
    if (strcmp(kind, "line") == 0) {
        constructor = make_line;
    } else if (strcmp(kind, "arc") == 0) {
        constructor = make_arc;
        ok = ok && (args[n++] = number(shape, "curvature", r, 0)) != NULL;
    } else if (strcmp(kind, "spiral") == 0) {
        constructor = make_spiral;
        ok = ok && (args[n++] = number(shape, "curvStart", r, 0)) != NULL;
        ok = ok && (args[n++] = number(shape, "curvEnd", r, 0)) != NULL;
    } else if (strcmp(kind, "poly3") == 0) {
        constructor = make_poly3;
        ok = ok && numbers_into(shape, POLY3, 4, r, args + n);
        n += 4;
    } else {
        constructor = make_param_poly3;
        ok = ok && numbers_into(shape, PARAM_POLY3, 8, r, args + n);
        n += 8;
        const char *raw;
        if (ok && attribute(shape, "pRange", &raw) == 1) {
            PyObject *key = text(raw);
            PyObject *p_range = key == NULL ? NULL : PyDict_GetItemWithError(p_ranges, key);
            Py_XDECREF(key);
            Py_XINCREF(p_range);
            args[n++] = p_range;
            ok = p_range != NULL;
        } else {
            ok = 0; /* no pRange (a finding) or an unusual one */
        }
    }
    if (ok) {
        args[n] = line_of(node);
    }
    n++;
    if (!ok || args[n - 1] == NULL) {
        for (Py_ssize_t i = 0; i < n; i++) {
            Py_XDECREF(args[i]);
        }
        return NULL;
    }
    return make_record(constructor, args, n, s_out);
}

PyObject *plan_view_list(const xmlNode *parent, const Reading *r)
{
    PyObject *out = ordered_records(parent, "geometry", r, geometry);
    if (out != NULL && PyList_GET_SIZE(out) == 0) {
        Py_DECREF(out);
        return FALLBACK; /* no <geometry>: a finding */
    }
    return out;
}
