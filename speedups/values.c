/*
 * One attribute, number, integer or line read the way lxml and the Python reader read it, and the cubic records
 * (<width>, <elevation>, <laneOffset>...) built from them.
 */
#include <math.h>
#include <string.h>

#include "read.h"

/* The head of lxml's _Element (lxml/etree.h, struct LxmlElement), stable since lxml 2: the proxied node follows the
 * document. xodrcheck/reader/fast.py checks the layout against lxml itself (node_line) before the module is used. */
typedef struct {
    PyObject_HEAD
    void *doc;
    xmlNode *c_node;
} Element;

size_t element_head_size(void)
{
    return sizeof(Element);
}

xmlNode *proxied_node(PyObject *el)
{
    if (element_type == NULL || !PyObject_TypeCheck(el, element_type)) {
        return NULL;
    }
    return ((Element *)el)->c_node;
}

xmlNode *node_of(PyObject *el)
{
    xmlNode *node = proxied_node(el);
    if (node == NULL || node->type != XML_ELEMENT_NODE || node->doc == NULL) {
        return NULL;
    }
    if (node->doc->intSubset != NULL || node->doc->extSubset != NULL) {
        return NULL; /* a DTD may give attributes default values, which el.get() would return */
    }
    return node;
}

int named(const xmlNode *node, const char *tag)
{
    return node->type == XML_ELEMENT_NODE && (node->ns == NULL || node->ns->href == NULL) &&
           strcmp((const char *)node->name, tag) == 0;
}

/* 1 and *value set: found; 0: absent; -1: present but not one text node. */
int attribute(const xmlNode *node, const char *name, const char **value)
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

int has_attribute(const xmlNode *node, const char *name)
{
    for (const xmlAttr *p = node->properties; p != NULL; p = p->next) {
        if (p->ns == NULL && strcmp((const char *)p->name, name) == 0) {
            return 1;
        }
    }
    return 0;
}

PyObject *line_of(const xmlNode *node)
{
    unsigned short line = node->line;
    if (line == 0 || line == 65535) {
        return FALLBACK;
    }
    return PyLong_FromLong(line);
}

PyObject *text(const char *value)
{
    return PyUnicode_DecodeUTF8(value, (Py_ssize_t)strlen(value), "strict");
}

/* el.get(name): the value as str, None when absent (new references); FALLBACK when unusual. */
PyObject *optional_text(const xmlNode *node, const char *name)
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

/* A number not in the cache yet, as Numbers.__missing__ makes it, when the text is a plain finite float: float()
 * converts what it reads with PyOS_string_to_double, once whitespace and underscores are taken out, so a text that
 * function reads whole, with neither, gives the same value. NULL without an error for anything else (Python's). */
static PyObject *parsed(const char *value, PyObject *key, PyObject *numbers)
{
    char *end;
    double x = PyOS_string_to_double(value, &end, NULL);
    if (x == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        return NULL;
    }
    if (end == value || *end != '\0' || !isfinite(x)) {
        return NULL;
    }
    PyObject *result = PyFloat_FromDouble(x);
    if (result != NULL && PyDict_GET_SIZE(numbers) < numbers_remembered && PyDict_SetItem(numbers, key, result) < 0) {
        Py_CLEAR(result);
    }
    return result;
}

/* numbers[el.get(name)], >= 0 with nonneg; FALLBACK when absent, unusual, invalid or negative. */
PyObject *number(const xmlNode *node, const char *name, const Reading *r, int nonneg)
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
        result = parsed(value, key, r->numbers);
        if (result == NULL && !PyErr_Occurred()) {
            result = PyObject_GetItem(r->numbers, key); /* Numbers.__missing__: parses, remembers, or ValueError */
        }
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
PyObject *integer(const xmlNode *node, const char *name)
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
PyObject *make(PyObject *constructor, PyObject **args, Py_ssize_t n)
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

/* make() a record whose first argument is its s (a float), and hand that s back when the record is made. */
PyObject *make_record(PyObject *constructor, PyObject **args, Py_ssize_t n, double *s_out)
{
    double s = args[0] != NULL ? PyFloat_AS_DOUBLE(args[0]) : 0.0;
    PyObject *record = make(constructor, args, n);
    if (record != NULL) {
        *s_out = s;
    }
    return record;
}

/* Append a record (stolen) to list if its s is not below the previous record's; -1 for out of order (a FALLBACK,
 * no error set) or an error. */
int append_in_order(PyObject *list, PyObject *record, double s, double *last)
{
    if (PyList_GET_SIZE(list) > 0 && s < *last) {
        Py_DECREF(record);
        return -1;
    }
    *last = s;
    int status = PyList_Append(list, record);
    Py_DECREF(record);
    return status;
}

PyObject *list_to_tuple(PyObject *list)
{
    if (list == NULL) {
        return NULL;
    }
    PyObject *tuple = PyList_AsTuple(list);
    Py_DECREF(list);
    return tuple;
}

/* <tag s a b c d> (sOffset with offset), s >= 0. */
PyObject *cubic(const xmlNode *node, const Reading *r, int offset, double *s_out)
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
    return make_record(make_cubic, args, 6, s_out);
}

/* <tag s a b c d>, as in a profile (s, not sOffset). */
PyObject *profile_cubic(const xmlNode *node, const Reading *r, double *s_out)
{
    return cubic(node, r, 0, s_out);
}

/* The <tag> children of parent built by build, as a list in ascending s. */
PyObject *ordered_records(const xmlNode *parent, const char *tag, const Reading *r, Builder build)
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
        double s = 0.0;
        PyObject *record = build(child, r, &s);
        if (record == NULL || append_in_order(out, record, s, &last) < 0) {
            Py_DECREF(out);
            return NULL;
        }
    }
    return out;
}
