/*
 * xodrcheck_speedups: the compiled fast path of xodrcheck's reader (xodrcheck/reader/fast.py).
 *
 * It builds the model records of the three parts of a road that hold most of a map's elements (<planView>, the
 * cubic profiles such as <elevationProfile>, and <lanes>) straight from libxml2's tree under an lxml element, without
 * an lxml proxy per element. It handles only the usual case: an element whose every record reads without a finding.
 * Anything else (a missing, invalid or out-of-order value, a repeated element, a line past 65534, a DTD, an attribute
 * with entity references...) makes the function return None and the pure-Python reader builds that part instead,
 * finding and all. Since the fast path reports nothing and changes nothing, the result is the Python reader's, value
 * for value; tests/xodrcheck/test_reader_fast.py checks that on every file of the corpus.
 *
 * What the Python reader does and this file mirrors:
 *   - el.tag == "name": an element node named so without a namespace (lxml spells a namespaced tag "{ns}name");
 *   - el.get(name): the first attribute of that name without a namespace (xmlGetNoNsProp), whose value here must be
 *     one text node (or empty);
 *   - el.sourceline: the node's line when it is 1..65534 (xmlGetLineNo); past that libxml2 guesses, so None here;
 *   - numbers[raw]: the read's Numbers cache itself (a dict subclass; its __missing__ parses and rejects non-finite
 *     values with ValueError), so every number is the float the Python reader gets;
 *   - int(raw): only [-]digits (at most 9) here; anything int() would read otherwise goes to Python.
 *
 * Records are made by the reader's own constructors (xodrcheck/reader/construct.py), handed over by configure().
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <string.h>
#include <libxml/tree.h>

/* The head of lxml's _Element (lxml/etree.h, struct LxmlElement), stable since lxml 2: the proxied node follows the
 * document. init_check() verifies the layout against lxml itself before the module is used. */
typedef struct {
    PyObject_HEAD
    void *doc;
    xmlNode *c_node;
} Element;

static PyTypeObject *element_type;
static PyObject *make_cubic, *make_line, *make_arc, *make_spiral, *make_poly3, *make_param_poly3;
static PyObject *make_road_mark, *make_speed, *make_lane_height, *make_lane, *make_lane_section;
static PyObject *lane_types, *p_ranges;

/* A result of NULL without a Python error set means: not the usual case, let the Python reader do it. */
#define FALLBACK NULL

typedef struct {
    PyObject *numbers;
    int layered;
} Reading;

static xmlNode *node_of(PyObject *el)
{
    if (element_type == NULL || !PyObject_TypeCheck(el, element_type)) {
        return NULL;
    }
    xmlNode *node = ((Element *)el)->c_node;
    if (node == NULL || node->type != XML_ELEMENT_NODE || node->doc == NULL) {
        return NULL;
    }
    if (node->doc->intSubset != NULL || node->doc->extSubset != NULL) {
        return NULL; /* a DTD may give attributes default values, which el.get() would return */
    }
    return node;
}

static int named(const xmlNode *node, const char *tag)
{
    return node->type == XML_ELEMENT_NODE && (node->ns == NULL || node->ns->href == NULL) &&
           strcmp((const char *)node->name, tag) == 0;
}

/* 1 and *value set: found; 0: absent; -1: present but not one text node. */
static int attribute(const xmlNode *node, const char *name, const char **value)
{
    for (const xmlAttr *p = node->properties; p != NULL; p = p->next) {
        if (p->ns == NULL && strcmp((const char *)p->name, name) == 0) {
            const xmlNode *text = p->children;
            if (text == NULL) {
                *value = "";
                return 1;
            }
            if (text->next == NULL && text->type == XML_TEXT_NODE && text->content != NULL) {
                *value = (const char *)text->content;
                return 1;
            }
            return -1;
        }
    }
    return 0;
}

static int has_attribute(const xmlNode *node, const char *name)
{
    for (const xmlAttr *p = node->properties; p != NULL; p = p->next) {
        if (p->ns == NULL && strcmp((const char *)p->name, name) == 0) {
            return 1;
        }
    }
    return 0;
}

static PyObject *line_of(const xmlNode *node)
{
    unsigned short line = node->line;
    if (line == 0 || line == 65535) {
        return FALLBACK;
    }
    return PyLong_FromLong(line);
}

static PyObject *text(const char *value)
{
    return PyUnicode_DecodeUTF8(value, (Py_ssize_t)strlen(value), "strict");
}

/* el.get(name): the value as str, None when absent (new references); FALLBACK when unusual. */
static PyObject *optional_text(const xmlNode *node, const char *name)
{
    const char *value;
    int found = attribute(node, name, &value);
    if (found < 0) {
        return FALLBACK;
    }
    if (found == 0) {
        Py_RETURN_NONE;
    }
    return text(value);
}

/* numbers[el.get(name)], >= 0 with nonneg; FALLBACK when absent, unusual, invalid or negative. */
static PyObject *number(const xmlNode *node, const char *name, const Reading *r, int nonneg)
{
    const char *value;
    if (attribute(node, name, &value) != 1) {
        return FALLBACK;
    }
    PyObject *key = text(value);
    if (key == NULL) {
        return NULL;
    }
    PyObject *result = PyDict_GetItemWithError(r->numbers, key);
    if (result != NULL) {
        Py_INCREF(result);
    } else if (!PyErr_Occurred()) {
        result = PyObject_GetItem(r->numbers, key); /* Numbers.__missing__: parses, remembers, or ValueError */
        if (result == NULL && PyErr_ExceptionMatches(PyExc_ValueError)) {
            PyErr_Clear();
        }
    }
    Py_DECREF(key);
    if (result == NULL) {
        return NULL;
    }
    if (!PyFloat_CheckExact(result) || (nonneg && PyFloat_AS_DOUBLE(result) < 0.0)) {
        Py_DECREF(result);
        return FALLBACK;
    }
    return result;
}

/* int(el.get(name)) for [-]digits (at most 9 of them); FALLBACK otherwise. */
static PyObject *integer(const xmlNode *node, const char *name)
{
    const char *value;
    if (attribute(node, name, &value) != 1) {
        return FALLBACK;
    }
    const char *p = value;
    int negative = 0;
    if (*p == '-') {
        negative = 1;
        p++;
    }
    long n = 0;
    int digits = 0;
    for (; *p >= '0' && *p <= '9'; p++) {
        if (++digits > 9) {
            return FALLBACK;
        }
        n = n * 10 + (*p - '0');
    }
    if (digits == 0 || *p != '\0') {
        return FALLBACK;
    }
    return PyLong_FromLong(negative ? -n : n);
}

/* Call a constructor with n arguments, stealing them (any of them NULL: release the others, return NULL). */
static PyObject *make(PyObject *constructor, PyObject **args, Py_ssize_t n)
{
    PyObject *result = NULL;
    Py_ssize_t i;
    for (i = 0; i < n; i++) {
        if (args[i] == NULL) {
            break;
        }
    }
    if (i == n) {
        result = PyObject_Vectorcall(constructor, args, (size_t)n, NULL);
    }
    for (i = 0; i < n; i++) {
        Py_XDECREF(args[i]);
    }
    return result;
}

/* Append a record (stolen) to list if its s is not below the previous record's; FALLBACK for out of order. */
static int append_in_order(PyObject *list, PyObject *record, PyObject *s, double *last)
{
    double value = PyFloat_AS_DOUBLE(s);
    if (PyList_GET_SIZE(list) > 0 && value < *last) {
        Py_DECREF(record);
        return -1;
    }
    *last = value;
    int status = PyList_Append(list, record);
    Py_DECREF(record);
    return status;
}

static PyObject *list_to_tuple(PyObject *list)
{
    if (list == NULL) {
        return NULL;
    }
    PyObject *tuple = PyList_AsTuple(list);
    Py_DECREF(list);
    return tuple;
}

/* ------------------------------------------------------------------------------------------------ cubic records */

/* <tag s a b c d> (sOffset with offset), s >= 0. */
static PyObject *cubic(const xmlNode *node, const Reading *r, int offset, PyObject **s_out)
{
    PyObject *args[6] = {
        number(node, offset ? "sOffset" : "s", r, 1),
        NULL, NULL, NULL, NULL, NULL,
    };
    if (args[0] == NULL) {
        return NULL;
    }
    args[1] = number(node, "a", r, 0);
    args[2] = args[1] ? number(node, "b", r, 0) : NULL;
    args[3] = args[2] ? number(node, "c", r, 0) : NULL;
    args[4] = args[3] ? number(node, "d", r, 0) : NULL;
    args[5] = args[4] ? line_of(node) : NULL;
    *s_out = args[0]; /* borrowed from the record once made */
    return make(make_cubic, args, 6);
}

/* The <tag> children of parent as a list of cubic records in ascending s. */
static PyObject *cubic_list(const xmlNode *parent, const char *tag, const Reading *r, int offset)
{
    PyObject *out = PyList_New(0);
    double last = 0.0;
    if (out == NULL) {
        return NULL;
    }
    for (const xmlNode *child = parent->children; child != NULL; child = child->next) {
        if (!named(child, tag)) {
            continue;
        }
        PyObject *s = NULL;
        PyObject *record = cubic(child, r, offset, &s);
        if (record == NULL || append_in_order(out, record, s, &last) < 0) {
            Py_DECREF(out);
            return NULL;
        }
    }
    return out;
}

/* ------------------------------------------------------------------------------------------------ plan view */

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

static PyObject *geometry(const xmlNode *node, const Reading *r)
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
    return make(constructor, args, n);
}

static PyObject *plan_view_list(const xmlNode *parent, const Reading *r)
{
    PyObject *out = PyList_New(0);
    double last = 0.0;
    if (out == NULL) {
        return NULL;
    }
    for (const xmlNode *child = parent->children; child != NULL; child = child->next) {
        if (!named(child, "geometry")) {
            continue;
        }
        PyObject *record = geometry(child, r);
        if (record == NULL) {
            Py_DECREF(out);
            return NULL;
        }
        PyObject *s = PyObject_GetAttrString(record, "s");
        if (s == NULL) {
            Py_DECREF(record);
            Py_DECREF(out);
            return NULL;
        }
        int status = append_in_order(out, record, s, &last);
        Py_DECREF(s);
        if (status < 0) {
            Py_DECREF(out);
            return NULL;
        }
    }
    if (PyList_GET_SIZE(out) == 0) {
        Py_DECREF(out);
        return FALLBACK; /* no <geometry>: a finding */
    }
    return out;
}

/* ------------------------------------------------------------------------------------------------ lanes */

typedef struct {
    PyObject *lists[5]; /* widths, borders, marks, speeds, heights */
    double last[5];
    PyObject *links[2]; /* predecessors, successors */
    int linked;
} LaneRecords;

enum { WIDTHS, BORDERS, MARKS, SPEEDS, HEIGHTS };

static PyObject *road_mark(const xmlNode *node, const Reading *r, PyObject **s_out)
{
    PyObject *args[7] = {number(node, "sOffset", r, 1), NULL, NULL, NULL, NULL, NULL, NULL};
    const char *kind;
    if (args[0] != NULL && attribute(node, "type", &kind) == 1) {
        args[1] = text(kind);
    }
    if (args[1] != NULL) {
        args[2] = optional_text(node, "weight");
        args[3] = args[2] ? optional_text(node, "color") : NULL;
        if (args[3] != NULL) {
            args[4] = has_attribute(node, "width") ? number(node, "width", r, 1) : Py_NewRef(Py_None);
        }
        args[5] = args[4] ? optional_text(node, "laneChange") : NULL;
        args[6] = args[5] ? line_of(node) : NULL;
    }
    *s_out = args[0];
    return make(make_road_mark, args, 7);
}

static PyObject *speed(const xmlNode *node, const Reading *r, PyObject **s_out)
{
    PyObject *args[4] = {number(node, "sOffset", r, 1), NULL, NULL, NULL};
    args[1] = args[0] ? number(node, "max", r, 1) : NULL;
    args[2] = args[1] ? optional_text(node, "unit") : NULL;
    args[3] = args[2] ? line_of(node) : NULL;
    *s_out = args[0];
    return make(make_speed, args, 4);
}

static PyObject *height(const xmlNode *node, const Reading *r, PyObject **s_out)
{
    PyObject *args[4] = {number(node, "sOffset", r, 1), NULL, NULL, NULL};
    args[1] = args[0] ? number(node, "inner", r, 0) : NULL;
    args[2] = args[1] ? number(node, "outer", r, 0) : NULL;
    args[3] = args[2] ? line_of(node) : NULL;
    *s_out = args[0];
    return make(make_lane_height, args, 4);
}

/* A lane's <link>: its predecessor and successor ids (no layer attribute in a layered file: that is Python's). */
static int lane_links(const xmlNode *link, const Reading *r, LaneRecords *rec)
{
    if (rec->linked) {
        return -1; /* a repeated <link>: a finding */
    }
    rec->linked = 1;
    for (const xmlNode *child = link->children; child != NULL; child = child->next) {
        int k;
        if (named(child, "predecessor")) {
            k = 0;
        } else if (named(child, "successor")) {
            k = 1;
        } else {
            continue;
        }
        if (r->layered && has_attribute(child, "layer")) {
            return -1;
        }
        PyObject *id = integer(child, "id");
        if (id == NULL) {
            return -1;
        }
        int status = PyList_Append(rec->links[k], id);
        Py_DECREF(id);
        if (status < 0) {
            return -1;
        }
    }
    return 0;
}

static int lane_record(const xmlNode *child, const Reading *r, LaneRecords *rec)
{
    PyObject *s = NULL;
    PyObject *record;
    int k;
    if (named(child, "roadMark")) {
        k = MARKS;
        record = road_mark(child, r, &s);
    } else if (named(child, "width")) {
        k = WIDTHS;
        record = cubic(child, r, 1, &s);
    } else if (named(child, "border")) {
        k = BORDERS;
        record = cubic(child, r, 1, &s);
    } else if (named(child, "link")) {
        return lane_links(child, r, rec);
    } else if (named(child, "speed")) {
        k = SPEEDS;
        record = speed(child, r, &s);
    } else if (named(child, "height")) {
        k = HEIGHTS;
        record = height(child, r, &s);
    } else {
        return 0;
    }
    if (record == NULL) {
        return -1;
    }
    return append_in_order(rec->lists[k], record, s, &rec->last[k]);
}

static PyObject *lane(const xmlNode *node, const Reading *r, int *is_centre)
{
    PyObject *args[14] = {NULL};
    const char *raw;
    LaneRecords rec = {{NULL}, {0.0}, {NULL}, 0};
    args[0] = integer(node, "id");
    if (args[0] == NULL || attribute(node, "type", &raw) != 1) {
        Py_XDECREF(args[0]);
        return NULL;
    }
    *is_centre = PyLong_AsLong(args[0]) == 0;
    args[9] = text(raw); /* type_name */
    args[1] = args[9] == NULL ? NULL : PyDict_GetItemWithError(lane_types, args[9]);
    Py_XINCREF(args[1]);
    if (args[1] != NULL) {
        int level = attribute(node, "level", &raw);
        if (level == 0 || (level == 1 && strcmp(raw, "false") == 0)) {
            args[2] = Py_NewRef(Py_False);
        } else if (level == 1 && strcmp(raw, "true") == 0) {
            args[2] = Py_NewRef(Py_True);
        }
    }
    int ok = args[2] != NULL;
    for (int k = 0; ok && k < 5; k++) {
        ok = (rec.lists[k] = PyList_New(0)) != NULL;
    }
    for (int k = 0; ok && k < 2; k++) {
        ok = (rec.links[k] = PyList_New(0)) != NULL;
    }
    for (const xmlNode *child = node->children; ok && child != NULL; child = child->next) {
        ok = lane_record(child, r, &rec) == 0;
    }
    if (ok) {
        args[3] = PyList_AsTuple(rec.links[0]);
        args[4] = PyList_AsTuple(rec.links[1]);
        args[5] = PyList_AsTuple(rec.lists[WIDTHS]);
        args[6] = PyList_AsTuple(rec.lists[BORDERS]);
        args[7] = PyList_AsTuple(rec.lists[MARKS]);
        args[8] = PyList_AsTuple(rec.lists[SPEEDS]);
        args[10] = line_of(node);
        args[11] = PyList_AsTuple(rec.lists[HEIGHTS]);
        args[12] = PyTuple_New(0);
        args[13] = PyTuple_New(0);
    }
    for (int k = 0; k < 5; k++) {
        Py_XDECREF(rec.lists[k]);
    }
    for (int k = 0; k < 2; k++) {
        Py_XDECREF(rec.links[k]);
    }
    if (!ok) {
        for (int i = 0; i < 14; i++) {
            Py_XDECREF(args[i]);
        }
        return NULL;
    }
    return make(make_lane, args, 14);
}

/* The lanes of a <left>, <center> or <right>; *has_centre set when one has id 0. */
static PyObject *side(const xmlNode *node, const Reading *r, int *has_centre)
{
    PyObject *out = PyList_New(0);
    if (out == NULL) {
        return NULL;
    }
    for (const xmlNode *child = node->children; child != NULL; child = child->next) {
        if (!named(child, "lane")) {
            continue;
        }
        int is_centre = 0;
        PyObject *built = lane(child, r, &is_centre);
        if (built == NULL || PyList_Append(out, built) < 0) {
            Py_XDECREF(built);
            Py_DECREF(out);
            return NULL;
        }
        Py_DECREF(built);
        *has_centre |= is_centre;
    }
    return list_to_tuple(out);
}

/* singleSide: "true"/"1" -> True, "false"/"0" -> False, absent -> None; FALLBACK for anything else. */
static PyObject *single_side(const xmlNode *node)
{
    const char *raw;
    int found = attribute(node, "singleSide", &raw);
    if (found == 0) {
        Py_RETURN_NONE;
    }
    if (found == 1 && (strcmp(raw, "true") == 0 || strcmp(raw, "1") == 0)) {
        Py_RETURN_TRUE;
    }
    if (found == 1 && (strcmp(raw, "false") == 0 || strcmp(raw, "0") == 0)) {
        Py_RETURN_FALSE;
    }
    return FALLBACK;
}

static PyObject *section(const xmlNode *node, const Reading *r)
{
    /* s, single_side, left, center, right, line, length */
    PyObject *args[7] = {number(node, "s", r, 1), NULL, NULL, NULL, NULL, NULL, NULL};
    args[1] = args[0] ? single_side(node) : NULL;
    if (args[1] != NULL) {
        args[6] = r->layered && has_attribute(node, "length") ? number(node, "length", r, 1) : Py_NewRef(Py_None);
    }
    int ok = args[6] != NULL;
    int has_centre = 0;
    for (const xmlNode *child = node->children; ok && child != NULL; child = child->next) {
        int k;
        if (named(child, "left")) {
            k = 2;
        } else if (named(child, "center")) {
            k = 3;
        } else if (named(child, "right")) {
            k = 4;
        } else {
            continue;
        }
        if (args[k] != NULL) {
            ok = 0; /* a repeated side: a finding */
        } else {
            int centre = 0;
            args[k] = side(child, r, &centre);
            ok = args[k] != NULL;
            if (k == 3) {
                has_centre = centre;
            }
        }
    }
    if (ok && has_centre) {
        for (int k = 2; k < 5; k++) {
            if (args[k] == NULL) {
                args[k] = PyTuple_New(0);
            }
        }
        args[5] = line_of(node);
        return make(make_lane_section, args, 7);
    }
    for (int i = 0; i < 7; i++) {
        Py_XDECREF(args[i]);
    }
    return NULL; /* FALLBACK (no centre lane 0 is a finding) or the error set */
}

static PyObject *lanes_pair(const xmlNode *node, const Reading *r)
{
    PyObject *offsets = PyList_New(0);
    PyObject *sections = PyList_New(0);
    double last_offset = 0.0, last_section = 0.0;
    int ok = offsets != NULL && sections != NULL;
    int seen = 0;
    for (const xmlNode *child = node->children; ok && child != NULL; child = child->next) {
        PyObject *s = NULL;
        PyObject *record;
        if (named(child, "laneSection")) {
            seen = 1;
            record = section(child, r);
            if (record != NULL) {
                s = PyObject_GetAttrString(record, "s");
                if (s == NULL) {
                    Py_CLEAR(record);
                }
            }
            ok = record != NULL && append_in_order(sections, record, s, &last_section) == 0;
            Py_XDECREF(s);
        } else if (named(child, "laneOffset")) {
            record = cubic(child, r, 0, &s);
            ok = record != NULL && append_in_order(offsets, record, s, &last_offset) == 0;
        }
    }
    PyObject *result = NULL;
    if (ok && seen) {
        result = Py_BuildValue("(NN)", PyList_AsTuple(offsets), PyList_AsTuple(sections));
    }
    Py_XDECREF(offsets);
    Py_XDECREF(sections);
    return result;
}

/* ------------------------------------------------------------------------------------------------ module */

static int reading(PyObject *const *args, Py_ssize_t nargs, const char *name, int with_layers, Reading *r,
                   xmlNode **node)
{
    Py_ssize_t expected = with_layers ? 3 : 2;
    if (nargs != expected) {
        PyErr_Format(PyExc_TypeError, "%s() takes %zd arguments", name, expected);
        return -1;
    }
    if (!PyDict_Check(args[1])) {
        PyErr_Format(PyExc_TypeError, "%s(): numbers must be the read's Numbers", name);
        return -1;
    }
    if (make_lane == NULL) {
        PyErr_SetString(PyExc_RuntimeError, "xodrcheck_speedups.configure() has not been called");
        return -1;
    }
    r->numbers = args[1];
    r->layered = with_layers ? PyObject_IsTrue(args[2]) : 0;
    if (r->layered < 0) {
        return -1;
    }
    *node = node_of(args[0]);
    return 0;
}

static PyObject *finish(PyObject *result)
{
    if (result == NULL && !PyErr_Occurred()) {
        Py_RETURN_NONE;
    }
    return result;
}

PyDoc_STRVAR(plan_view_doc, "plan_view(el, numbers) -> tuple of geometries, or None for the Python reader.");

static PyObject *py_plan_view(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    Reading r;
    xmlNode *node;
    if (reading(args, nargs, "plan_view", 0, &r, &node) < 0) {
        return NULL;
    }
    return finish(node == NULL ? NULL : list_to_tuple(plan_view_list(node, &r)));
}

PyDoc_STRVAR(profile_doc, "profile(el, numbers, tag) -> tuple of cubics in order of s, or None for the Python reader.");

static PyObject *py_profile(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    Reading r;
    xmlNode *node;
    if (nargs != 3 || !PyUnicode_Check(args[2])) {
        PyErr_SetString(PyExc_TypeError, "profile(el, numbers, tag)");
        return NULL;
    }
    const char *tag = PyUnicode_AsUTF8(args[2]);
    if (tag == NULL || reading(args, 2, "profile", 0, &r, &node) < 0) {
        return NULL;
    }
    return finish(node == NULL ? NULL : list_to_tuple(cubic_list(node, tag, &r, 0)));
}

PyDoc_STRVAR(lanes_doc,
             "lanes(el, numbers, layered) -> (laneOffset cubics, lane sections) of a <lanes>, or None for the Python "
             "reader.");

static PyObject *py_lanes(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    Reading r;
    xmlNode *node;
    if (reading(args, nargs, "lanes", 1, &r, &node) < 0) {
        return NULL;
    }
    return finish(node == NULL ? NULL : lanes_pair(node, &r));
}

static PyObject **const CONFIGURED[] = {
    &make_cubic, &make_line, &make_arc, &make_spiral, &make_poly3, &make_param_poly3, &make_road_mark,
    &make_speed, &make_lane_height, &make_lane, &make_lane_section, &lane_types, &p_ranges,
};
static const char *const CONFIGURED_NAMES[] = {
    "make_cubic", "make_line", "make_arc", "make_spiral", "make_poly3", "make_param_poly3", "make_road_mark",
    "make_speed", "make_lane_height", "make_lane", "make_lane_section", "lane_types", "p_ranges",
};
#define N_CONFIGURED (sizeof(CONFIGURED) / sizeof(CONFIGURED[0]))

PyDoc_STRVAR(configure_doc,
             "configure(element_type, **parts): lxml's _Element class, the reader's constructors (make_cubic, ... "
             "make_lane_section) and its lane_types and p_ranges dicts.");

static PyObject *py_configure(PyObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *type;
    if (!PyArg_ParseTuple(args, "O!", &PyType_Type, &type) || kwargs == NULL) {
        if (!PyErr_Occurred()) {
            PyErr_SetString(PyExc_TypeError, "configure(element_type, **parts)");
        }
        return NULL;
    }
    PyObject *values[N_CONFIGURED];
    for (size_t i = 0; i < N_CONFIGURED; i++) {
        values[i] = PyDict_GetItemString(kwargs, CONFIGURED_NAMES[i]);
        if (values[i] == NULL) {
            PyErr_Format(PyExc_TypeError, "configure(): %s is missing", CONFIGURED_NAMES[i]);
            return NULL;
        }
    }
    if (!PyDict_Check(values[N_CONFIGURED - 1]) || !PyDict_Check(values[N_CONFIGURED - 2])) {
        PyErr_SetString(PyExc_TypeError, "configure(): lane_types and p_ranges are dicts");
        return NULL;
    }
    for (size_t i = 0; i < N_CONFIGURED; i++) {
        Py_XSETREF(*CONFIGURED[i], Py_NewRef(values[i]));
    }
    Py_XSETREF(element_type, (PyTypeObject *)Py_NewRef(type));
    Py_RETURN_NONE;
}

PyDoc_STRVAR(node_line_doc, "node_line(el) -> the line libxml2 stored for el's node (a check of the layout).");

static PyObject *py_node_line(PyObject *self, PyObject *el)
{
    if (element_type == NULL || !PyObject_TypeCheck(el, element_type) || ((Element *)el)->c_node == NULL) {
        PyErr_SetString(PyExc_TypeError, "node_line() takes a configured lxml element");
        return NULL;
    }
    const xmlNode *node = ((Element *)el)->c_node;
    return Py_BuildValue("(sl)", node->name == NULL ? "" : (const char *)node->name, (long)node->line);
}

static PyMethodDef methods[] = {
    {"configure", (PyCFunction)(void (*)(void))py_configure, METH_VARARGS | METH_KEYWORDS, configure_doc},
    {"plan_view", (PyCFunction)(void (*)(void))py_plan_view, METH_FASTCALL, plan_view_doc},
    {"profile", (PyCFunction)(void (*)(void))py_profile, METH_FASTCALL, profile_doc},
    {"lanes", (PyCFunction)(void (*)(void))py_lanes, METH_FASTCALL, lanes_doc},
    {"node_line", py_node_line, METH_O, node_line_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "xodrcheck_speedups",
    "The compiled fast path of xodrcheck's reader (used through xodrcheck.reader.fast).",
    -1,
    methods,
};

PyMODINIT_FUNC PyInit_xodrcheck_speedups(void)
{
    PyObject *m = PyModule_Create(&module);
    if (m != NULL && PyModule_AddIntConstant(m, "LIBXML_VERSION", LIBXML_VERSION) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
