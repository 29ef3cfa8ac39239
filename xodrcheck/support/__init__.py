"""Plumbing shared by the rest of xodrcheck and knowing nothing of OpenDRIVE: output files, many-file runs, caches,
memory, work counts, array index arithmetic, package data and how numbers are written in messages."""
