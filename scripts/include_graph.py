#!/usr/bin/env python3
"""The folder-to-folder include graph of IMPM, and its cycles.

Reads every `#include <impm/FOLDER/...>` line of the files under
include/impm/ and source/. A file in include/impm/X/ or source/X/ belongs
to folder X; a file directly in source/ to its name without the suffix
(source/main.cc: 'main'). An include of a folder's own headers is not an
edge.

Prints one line per folder, `folder -> a, b, c` (the folders it includes;
'(none)' if it includes none), then every cycle: each strongly connected
component of more than one folder, with the folders of it that include each
other directly ('both ways') and, per edge inside it, how many include lines
make that edge and one of them.

Exit status: 1 if there is a cycle, 0 otherwise.

Usage: scripts/include_graph.py [SOURCE_DIRECTORY]
(default: the directory above this script's).
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]impm/([^/>"]+)/[^>"]*[>"]')


def folder_of(relative_path):
    """The folder a file (path relative to the source directory) belongs
    to, or None for a file outside include/impm/ and source/."""
    parts = relative_path.split(os.sep)
    if parts[:2] == ['include', 'impm'] and len(parts) > 3:
        return parts[2]
    if parts[0] == 'source':
        if len(parts) > 2:
            return parts[1]
        if len(parts) == 2:
            return os.path.splitext(os.path.splitext(parts[1])[0])[0]
    return None


def read_graph(root):
    """edges[a][b]: the include lines (file, header) by which folder a
    includes folder b; every folder found is a key."""
    edges = {}
    for top in (os.path.join(root, 'include', 'impm'),
                os.path.join(root, 'source')):
        for directory, _, files in os.walk(top):
            for name in sorted(files):
                path = os.path.join(directory, name)
                relative = os.path.relpath(path, root)
                source = folder_of(relative)
                if source is None:
                    continue
                edges.setdefault(source, {})
                try:
                    lines = open(path, encoding='utf-8',
                                 errors='replace').read().splitlines()
                except OSError:
                    continue
                for line in lines:
                    match = INCLUDE.match(line)
                    if not match:
                        continue
                    target = match.group(1)
                    edges.setdefault(target, {})
                    if target != source:
                        header = line.split('impm/', 1)[1].rstrip('>" \t')
                        edges[source].setdefault(target, []).append(
                            (relative, 'impm/' + header))
    return edges


def strongly_connected_components(edges):
    """Tarjan's algorithm (iterative); components in a stable order."""
    index, low, on_stack, stack, components = {}, {}, set(), [], []
    counter = 0
    for start in sorted(edges):
        if start in index:
            continue
        work = [(start, iter(sorted(edges[start])))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            advanced = False
            for successor in successors:
                if successor not in index:
                    index[successor] = low[successor] = counter
                    counter += 1
                    stack.append(successor)
                    on_stack.add(successor)
                    work.append((successor, iter(sorted(edges[successor]))))
                    advanced = True
                    break
                if successor in on_stack:
                    low[node] = min(low[node], index[successor])
            if advanced:
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                components.append(sorted(component))
    return sorted(components)


def main():
    root = (sys.argv[1] if len(sys.argv) > 1 else
            os.path.join(os.path.dirname(os.path.abspath(__file__)), '..'))
    edges = read_graph(root)
    if not edges:
        print('no files found under', os.path.join(root, 'include', 'impm'),
              'or', os.path.join(root, 'source'))
        return 2
    for folder in sorted(edges):
        targets = sorted(edges[folder])
        print('%s -> %s' % (folder, ', '.join(targets) if targets else
                            '(none)'))
    cycles = [c for c in strongly_connected_components(edges) if len(c) > 1]
    print()
    if not cycles:
        print('no cycles')
        return 0
    print('cycles (strongly connected components of more than one folder):')
    for component in cycles:
        members = set(component)
        print('cycle: ' + ', '.join(component))
        both = ['%s <-> %s' % (a, b) for a in component for b in component
                if a < b and b in edges[a] and a in edges[b]]
        if both:
            print('  both ways: ' + ', '.join(both))
        for a in component:
            for b in sorted(edges[a]):
                if b in members:
                    lines = edges[a][b]
                    print('  %s -> %s: %d include%s, e.g. %s: %s' %
                          (a, b, len(lines), '' if len(lines) == 1 else 's',
                           lines[0][0], lines[0][1]))
    return 1


if __name__ == '__main__':
    sys.exit(main())
