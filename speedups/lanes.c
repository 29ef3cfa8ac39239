/* <lanes>: the laneOffset profile and the lane sections with their lanes and the lanes' records. */
#include <string.h>

#include "read.h"

typedef struct {
    PyObject *lists[5]; /* widths, borders, marks, speeds, heights */
    double last[5];
    PyObject *links[2]; /* predecessors, successors */
    int linked;
} LaneRecords;

enum { WIDTHS, BORDERS, MARKS, SPEEDS, HEIGHTS };

static PyObject *road_mark(const xmlNode *node, const Reading *r, double *s_out)
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
    return make_record(make_road_mark, args, 7, s_out);
}

static PyObject *speed(const xmlNode *node, const Reading *r, double *s_out)
{
    PyObject *args[4] = {number(node, "sOffset", r, 1), NULL, NULL, NULL};
    args[1] = args[0] ? number(node, "max", r, 1) : NULL;
    args[2] = args[1] ? optional_text(node, "unit") : NULL;
    args[3] = args[2] ? line_of(node) : NULL;
    return make_record(make_speed, args, 4, s_out);
}

static PyObject *height(const xmlNode *node, const Reading *r, double *s_out)
{
    PyObject *args[4] = {number(node, "sOffset", r, 1), NULL, NULL, NULL};
    args[1] = args[0] ? number(node, "inner", r, 0) : NULL;
    args[2] = args[1] ? number(node, "outer", r, 0) : NULL;
    args[3] = args[2] ? line_of(node) : NULL;
    return make_record(make_lane_height, args, 4, s_out);
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
    double s = 0.0;
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
    /* a lane with @direction (1.8) is Python's: the model's direction is read there, by version */
    if (args[0] == NULL || attribute(node, "type", &raw) != 1 || has_attribute(node, "direction")) {
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
        /* predecessors, successors, widths, borders, marks, speeds: arguments 3 to 8 */
        PyObject *const lists[] = {rec.links[0],        rec.links[1],       rec.lists[WIDTHS],
                                   rec.lists[BORDERS], rec.lists[MARKS], rec.lists[SPEEDS]};
        for (int i = 0; ok && i < 6; i++) {
            ok = (args[3 + i] = PyList_AsTuple(lists[i])) != NULL;
        }
        ok = ok && (args[10] = line_of(node)) != NULL;
        ok = ok && (args[11] = PyList_AsTuple(rec.lists[HEIGHTS])) != NULL;
        ok = ok && (args[12] = PyTuple_New(0)) != NULL;
        ok = ok && (args[13] = PyTuple_New(0)) != NULL;
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

static PyObject *section(const xmlNode *node, const Reading *r, double *s_out)
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
        return make_record(make_lane_section, args, 7, s_out);
    }
    for (int i = 0; i < 7; i++) {
        Py_XDECREF(args[i]);
    }
    return NULL; /* FALLBACK (no centre lane 0 is a finding) or the error set */
}

PyObject *lanes_pair(const xmlNode *node, const Reading *r)
{
    PyObject *offsets = PyList_New(0);
    PyObject *sections = PyList_New(0);
    double last_offset = 0.0, last_section = 0.0;
    int ok = offsets != NULL && sections != NULL;
    int seen = 0;
    for (const xmlNode *child = node->children; ok && child != NULL; child = child->next) {
        double s = 0.0;
        PyObject *record;
        if (named(child, "laneSection")) {
            seen = 1;
            record = section(child, r, &s);
            ok = record != NULL && append_in_order(sections, record, s, &last_section) == 0;
        } else if (named(child, "laneOffset")) {
            record = cubic(child, r, 0, &s);
            ok = record != NULL && append_in_order(offsets, record, s, &last_offset) == 0;
        }
    }
    PyObject *result = NULL;
    if (ok && seen) {
        PyObject *offset_tuple = PyList_AsTuple(offsets);
        PyObject *section_tuple = offset_tuple == NULL ? NULL : PyList_AsTuple(sections);
        if (section_tuple != NULL) {
            result = PyTuple_Pack(2, offset_tuple, section_tuple);
        }
        Py_XDECREF(offset_tuple);
        Py_XDECREF(section_tuple);
    }
    Py_XDECREF(offsets);
    Py_XDECREF(sections);
    return result;
}
