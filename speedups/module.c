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
 * What the Python reader does and values.c mirrors:
 *   - el.tag == "name": an element node named so without a namespace (lxml spells a namespaced tag "{ns}name");
 *   - el.get(name): the first attribute of that name without a namespace (xmlGetNoNsProp), whose value here must be
 *     one text node (or empty);
 *   - el.sourceline: the node's line when it is 1..65534 (xmlGetLineNo); past that libxml2 guesses, so None here;
 *   - numbers[raw]: the read's Numbers cache itself (a dict subclass; its __missing__ parses and rejects non-finite
 *     values with ValueError), so every number is the float the Python reader gets;
 *   - int(raw): only [-]digits (at most 9) here; anything int() would read otherwise goes to Python.
 *
 * Records are made by the reader's own constructors (xodrcheck/reader/construct.py), handed over by configure().
 * The walk holds libxml2's nodes while it calls them and the number cache: the tree must not change during a call
 * (read() builds from a tree nobody else sees), and numbers must be the reader's Numbers itself, not a subclass.
 */
#include <string.h>

#include "read.h"

PyTypeObject *element_type, *numbers_type;
PyObject *make_cubic, *make_line, *make_arc, *make_spiral, *make_poly3, *make_param_poly3;
PyObject *make_road_mark, *make_speed, *make_lane_height, *make_lane, *make_lane_section;
PyObject *lane_types, *p_ranges;
Py_ssize_t numbers_remembered;

static int reading(PyObject *const *args, Py_ssize_t nargs, const char *name, int with_layers, Reading *r,
                   xmlNode **node)
{
    Py_ssize_t expected = with_layers ? 3 : 2;
    if (nargs != expected) {
        PyErr_Format(PyExc_TypeError, "%s() takes %zd arguments", name, expected);
        return -1;
    }
    if (numbers_type == NULL || !Py_IS_TYPE(args[1], numbers_type)) {
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
    Py_ssize_t size;
    const char *tag = PyUnicode_AsUTF8AndSize(args[2], &size);
    if (tag == NULL || reading(args, 2, "profile", 0, &r, &node) < 0) {
        return NULL;
    }
    if ((size_t)size != strlen(tag) || tag[0] == '{') {
        Py_RETURN_NONE; /* a tag with a namespace or a NUL: the Python reader's */
    }
    return finish(node == NULL ? NULL : list_to_tuple(ordered_records(node, tag, &r, profile_cubic)));
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
             "configure(element_type, numbers_type, remembered, **parts): lxml's _Element class, the reader's Numbers "
             "class and how many values it keeps, "
             "its constructors (make_cubic, ... make_lane_section) and its lane_types and p_ranges dicts.");

/* Whether type is lxml's _Element (or a subclass) laid out as this module reads it. */
static int is_element_type(PyTypeObject *type)
{
    PyObject *etree = PyImport_ImportModule("lxml.etree");
    PyObject *base = etree == NULL ? NULL : PyObject_GetAttrString(etree, "_Element");
    Py_XDECREF(etree);
    if (base == NULL) {
        return -1;
    }
    int fits = PyType_Check(base) && PyType_IsSubtype(type, (PyTypeObject *)base) &&
               (size_t)((PyTypeObject *)base)->tp_basicsize >= element_head_size();
    Py_DECREF(base);
    return fits;
}

static PyObject *py_configure(PyObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *type, *numbers;
    Py_ssize_t remembered;
    if (!PyArg_ParseTuple(args, "O!O!n", &PyType_Type, &type, &PyType_Type, &numbers, &remembered) ||
        kwargs == NULL) {
        if (!PyErr_Occurred()) {
            PyErr_SetString(PyExc_TypeError, "configure(element_type, numbers_type, remembered, **parts)");
        }
        return NULL;
    }
    int fits = is_element_type((PyTypeObject *)type);
    if (fits <= 0) {
        if (fits == 0) {
            PyErr_SetString(PyExc_TypeError, "configure(): element_type is not lxml.etree._Element");
        }
        return NULL;
    }
    if (!PyType_IsSubtype((PyTypeObject *)numbers, &PyDict_Type)) {
        PyErr_SetString(PyExc_TypeError, "configure(): numbers_type is not a dict class");
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
    Py_XSETREF(numbers_type, (PyTypeObject *)Py_NewRef(numbers));
    numbers_remembered = remembered;
    Py_RETURN_NONE;
}

PyDoc_STRVAR(node_line_doc, "node_line(el) -> the line libxml2 stored for el's node (a check of the layout).");

static PyObject *py_node_line(PyObject *self, PyObject *el)
{
    const xmlNode *node = proxied_node(el);
    if (node == NULL) {
        PyErr_SetString(PyExc_TypeError, "node_line() takes a configured lxml element");
        return NULL;
    }
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

/* What xodrcheck/reader/fast.py expects (its CONTRACT): raised whenever what the module reads, or how, changes, so
 * a module built from older sources is left unused rather than trusted. */
#define CONTRACT 2

PyMODINIT_FUNC PyInit_xodrcheck_speedups(void)
{
    PyObject *m = PyModule_Create(&module);
    if (m != NULL && (PyModule_AddIntConstant(m, "LIBXML_VERSION", LIBXML_VERSION) < 0 ||
                      PyModule_AddIntConstant(m, "CONTRACT", CONTRACT) < 0)) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
