#!/usr/bin/python3
"""Checks that every point file in a directory is complete and readable the
way ParaView reads it (VTK's XML readers, from Debian's python3-vtk9): each
.vtu and .pvtu parses without an error and holds points, each .pvd is
well-formed XML naming files that exist, and no *.tmp file is left.
Prints one line per problem and exits 1 if there is any.

Usage: check_point_files.py DIRECTORY"""
import glob
import os
import sys
import xml.etree.ElementTree as ElementTree

import vtk


class ErrorCatcher:
    """Records VTK's error and warning events instead of printing them."""

    def __init__(self):
        self.messages = []

    def __call__(self, caller, event):
        self.messages.append(event)


def read(reader_class, path):
    reader = reader_class()
    catcher = ErrorCatcher()
    reader.AddObserver("ErrorEvent", catcher)
    reader.GetExecutive().AddObserver("ErrorEvent", catcher)
    reader.SetFileName(path)
    reader.Update()
    output = reader.GetOutput()
    n_points = output.GetNumberOfPoints() if output else 0
    return catcher.messages, n_points


def main(directory):
    vtk.vtkObject.GlobalWarningDisplayOff()
    problems = []
    for path in glob.glob(os.path.join(directory, "*.tmp")):
        problems.append(f"{path}: a temporary file is left")
    for path in sorted(glob.glob(os.path.join(directory, "*.vtu"))):
        errors, n_points = read(vtk.vtkXMLUnstructuredGridReader, path)
        if errors or n_points == 0:
            problems.append(f"{path}: not readable ({n_points} points)")
    for path in sorted(glob.glob(os.path.join(directory, "*.pvtu"))):
        errors, n_points = read(vtk.vtkXMLPUnstructuredGridReader, path)
        if errors or n_points == 0:
            problems.append(f"{path}: not readable ({n_points} points)")
    for path in sorted(glob.glob(os.path.join(directory, "*.pvd"))):
        try:
            root = ElementTree.parse(path).getroot()
        except ElementTree.ParseError as error:
            problems.append(f"{path}: not well-formed ({error})")
            continue
        for data_set in root.iter("DataSet"):
            named = os.path.join(directory, data_set.get("file"))
            if not os.path.exists(named):
                problems.append(f"{path}: names {named}, which does not exist")
    for problem in problems:
        print(problem)
    n_files = len(glob.glob(os.path.join(directory, "*.*vt*"))) + len(
        glob.glob(os.path.join(directory, "*.pvd")))
    print(f"check_point_files: {n_files} files, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
