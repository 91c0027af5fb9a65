#!/usr/bin/env python3
"""Checks that every #include "folder/..." in src/ names a folder its CMake library may use.

usage: check-layers.py SRC_DIR LAYERS_FILE [--graph]

LAYERS_FILE (written by CMake to BUILD/layers.txt) has one line per folder: "folder: used;folders".
A folder may include its own headers and those of every folder reachable through that list. With
--graph, prints the folders' include graph, each folder with the folders it includes, and the
groups of folders that include each other (the layers allow two: shapes <-> emitters and
integrators <-> scene).
"""
import os
import re
import sys

INCLUDE = re.compile(r'\s*#\s*include\s+"([a-z_]+)/[^"]+"')


def read_layers(path):
    layers = {}
    for line in open(path):
        if ':' in line:
            folder, used = line.split(':', 1)
            layers[folder.strip()] = {u for u in used.strip().split(';') if u}
    return layers


def reachable(layers, folder):
    seen, todo = set(), [folder]
    while todo:
        for used in layers.get(todo.pop(), ()):
            if used not in seen:
                seen.add(used)
                todo.append(used)
    return seen


def include_graph(src):
    """{folder: {included folder: [(file, line number), ...]}} over src/."""
    graph = {}
    for directory, _, files in os.walk(src):
        for name in sorted(files):
            path = os.path.join(directory, name)
            folder = os.path.relpath(path, src).split(os.sep)[0]
            edges = graph.setdefault(folder, {})
            with open(path, errors='replace') as text:
                for number, line in enumerate(text, 1):
                    match = INCLUDE.match(line)
                    if match and match.group(1) != folder and os.path.isdir(os.path.join(src, match.group(1))):
                        edges.setdefault(match.group(1), []).append((os.path.relpath(path, src), number))
    return graph


def cycles(graph):
    """The folders that include each other, directly or through others (Tarjan's strongly connected
    components of more than one folder)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(folder):
        index[folder] = low[folder] = len(index)
        stack.append(folder)
        on_stack.add(folder)
        for used in graph.get(folder, ()):
            if used not in index:
                visit(used)
                low[folder] = min(low[folder], low[used])
            elif used in on_stack:
                low[folder] = min(low[folder], index[used])
        if low[folder] == index[folder]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == folder:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for folder in sorted(graph):
        if folder not in index:
            visit(folder)
    return sorted(found)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    src, layers = sys.argv[1], read_layers(sys.argv[2])
    graph = include_graph(src)
    problems = []
    for folder, edges in sorted(graph.items()):
        if folder not in layers:
            problems.append(f"src/{folder}/ has no CMake library (columba_library in CMakeLists.txt)")
            continue
        allowed = reachable(layers, folder)
        for used, places in sorted(edges.items()):
            if used not in allowed:
                for file, number in places:
                    problems.append(f"src/{file}:{number}: {folder}/ may not include {used}/ "
                                    f"(columba_{folder} uses only: {', '.join(sorted(layers[folder])) or 'nothing'})")
    if '--graph' in sys.argv:
        for folder in sorted(graph):
            print(f"{folder} -> {', '.join(sorted(graph[folder])) or '(nothing)'}")
        print("folders that include each other:", '; '.join(' <-> '.join(c) for c in cycles(graph)) or 'none')
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        sys.exit(1)
    print(f"layering: {sum(len(e) for e in graph.values())} folder links in {len(graph)} folders, all allowed")


if __name__ == '__main__':
    main()
