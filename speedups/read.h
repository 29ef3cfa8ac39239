/*
 * What the units of xodrcheck_speedups share: the reading state, the configured constructors and the helpers that
 * read one attribute, number or line the way lxml and the Python reader do (values.c).
 */
#ifndef XODRCHECK_SPEEDUPS_READ_H
#define XODRCHECK_SPEEDUPS_READ_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <libxml/tree.h>

/* A result of NULL without a Python error set means: not the usual case, let the Python reader do it. */
#define FALLBACK NULL

typedef struct {
    PyObject *numbers; /* the read's Numbers: attribute text -> float */
    int layered;       /* OpenDRIVE 1.9 lane layers are read */
} Reading;

/* Set by configure() (module.c): lxml's _Element, the reader's constructors and its lookup tables. */
extern PyTypeObject *element_type, *numbers_type;
extern PyObject *make_cubic, *make_line, *make_arc, *make_spiral, *make_poly3, *make_param_poly3;
extern PyObject *make_road_mark, *make_speed, *make_lane_height, *make_lane, *make_lane_section;
extern PyObject *lane_types, *p_ranges;
extern Py_ssize_t numbers_remembered; /* how many values Numbers keeps (its _REMEMBER) */

/* values.c */
size_t element_head_size(void);      /* the bytes of lxml's _Element this module reads */
xmlNode *proxied_node(PyObject *el); /* the node under an lxml element, or NULL */
xmlNode *node_of(PyObject *el);      /* ... when it is an element the fast path may read */
int named(const xmlNode *node, const char *tag);
int attribute(const xmlNode *node, const char *name, const char **value);
int has_attribute(const xmlNode *node, const char *name);
PyObject *line_of(const xmlNode *node);
PyObject *text(const char *value);
PyObject *optional_text(const xmlNode *node, const char *name);
PyObject *number(const xmlNode *node, const char *name, const Reading *r, int nonneg);
PyObject *integer(const xmlNode *node, const char *name);
PyObject *make(PyObject *constructor, PyObject **args, Py_ssize_t n);
PyObject *make_record(PyObject *constructor, PyObject **args, Py_ssize_t n, double *s_out);
int append_in_order(PyObject *list, PyObject *record, double s, double *last);
PyObject *list_to_tuple(PyObject *list);
PyObject *cubic(const xmlNode *node, const Reading *r, int offset, double *s_out);
PyObject *profile_cubic(const xmlNode *node, const Reading *r, double *s_out);
/* A record of one element and its s; NULL without an error: FALLBACK. */
typedef PyObject *(*Builder)(const xmlNode *node, const Reading *r, double *s_out);
PyObject *ordered_records(const xmlNode *parent, const char *tag, const Reading *r, Builder build);

/* planview.c */
PyObject *plan_view_list(const xmlNode *parent, const Reading *r);

/* lanes.c */
PyObject *lanes_pair(const xmlNode *node, const Reading *r);

#endif
