#!/usr/bin/python3
"""The plug-in reference, generated from the documentation blocks of the sources.

Usage:
  plugin-docs.py SRC_DIR OUT_DIR          writes OUT_DIR/<kind>.md, one page per plug-in kind
  plugin-docs.py --check SRC_DIR OUT_DIR  fails (exit 1), naming FILE:LINE, when a registered plug-in
                                          has no block, a parameter it reads is undocumented, a
                                          documented one is never read, or a page in OUT_DIR differs
                                          from what the blocks give
  plugin-docs.py --reads SRC_DIR          lists, per plug-in, the parameters it reads and where

A block opens a plug-in's .cpp file:

  /*! plugin bsdf diffuse
  A smooth diffuse surface (the description: Markdown, any number of lines).
  Mitsuba 3: how it differs from Mitsuba 3's plug-in of that name.
  uses: helper_block, other_block
  | parameter   | type                | default | meaning        | Mitsuba 3 |
  | reflectance | spectrum or texture | 0.5     | diffuse albedo | same      |
  */

One block may name several plug-ins of one kind (`/*! plugin bsdf barbulebsdf barbulebsdfev`).
Parameters read by shared helper functions are documented once, in a block of the helper's file,
`/*! parameters NAME` followed by the table (and optionally a description line), which a plug-in
block pulls in with `uses: NAME`.

What a plug-in reads is found in its factory (the function given to `r.add` in
src/builtin/builtin_plugins.cpp) and, transitively, in every function taking `const Properties&
props` that it passes `props` to: the string literals in `props.getX("name", ...)`,
`props.has("name")`, `props.isString("name")`, `props.namedChild<T>("name")` and in the argument
after `props` of any call `f(props, "name", ...)`. A name given as a variable in those places is not
a literal and is not seen; the literal at the call site is.
"""
import os
import re
import sys

KIND_TITLES = {
    "integrator": ("integrators", "Integrators"),
    "sensor": ("sensors", "Sensors"),
    "film": ("films", "Films"),
    "rfilter": ("rfilters", "Reconstruction filters"),
    "sampler": ("samplers", "Samplers"),
    "emitter": ("emitters", "Emitters"),
    "bsdf": ("bsdfs", "BSDFs"),
    "shape": ("shapes", "Shapes"),
    "texture": ("textures", "Textures"),
    "medium": ("media", "Participating media"),
    "phase": ("phases", "Phase functions"),
    "volume": ("volumes", "Volumes"),
}
KIND_ORDER = list(KIND_TITLES)
COLUMNS = ["parameter", "type", "default", "meaning", "Mitsuba 3"]

READ_METHODS = r"(?:get[A-Za-z]*|has|isString|isVector|namedChild\s*<[^<>()]*>)"


class Problem(Exception):
    pass


def strip_comments(text):
    """Comments blanked out (newlines kept, so offsets and lines stay), string literals kept."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == "/" and i + 1 < n and text[i + 1] == "/":
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif c == "/" and i + 1 < n and text[i + 1] == "*":
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == '"' or c == "'":
            if c == '"' and i > 0 and text[i - 1] == "R":  # raw string R"(...)"
                m = re.match(r'"([^(]*)\(', text[i:])
                end = text.find(")" + m.group(1) + '"', i) if m else -1
                if end >= 0:
                    j = end + len(m.group(1)) + 2
                    out.append(text[i:j])
                    i = j
                    continue
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(text[i : j + 1])
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def blank_strings(code):
    """String and character literals blanked (same length), for brace and paren matching."""
    return re.sub(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', lambda m: '"' + " " * (len(m.group(0)) - 2) + '"', code)


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def matching(code, open_at, opening, closing):
    depth = 0
    for k in range(open_at, len(code)):
        if code[k] == opening:
            depth += 1
        elif code[k] == closing:
            depth -= 1
            if depth == 0:
                return k
    return len(code) - 1


def first_argument(code, start):
    """The text of the call argument starting at `start`, up to its comma or closing paren."""
    depth = 0
    for k in range(start, len(code)):
        ch = code[k]
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            if depth == 0:
                return start, k
            depth -= 1
        elif ch == "," and depth == 0:
            return start, k
    return start, len(code)


class SourceFile:
    def __init__(self, path, rel):
        self.path, self.rel = path, rel
        with open(path, encoding="utf-8") as f:
            self.text = f.read()
        self.code = strip_comments(self.text)
        self.flat = blank_strings(self.code)
        self.functions = []  # (name, body start, body end)
        for m in re.finditer(r"const\s+Properties\s*&\s*(?:props\b)?(?=\s*[,)])", self.flat):
            # Back to the parameter list's opening paren, then the function's name before it.
            depth, k = 0, m.start()
            while k > 0:
                k -= 1
                if self.flat[k] == ")":
                    depth += 1
                elif self.flat[k] == "(":
                    if depth == 0:
                        break
                    depth -= 1
            name = re.search(r"([A-Za-z_]\w*)\s*$", self.flat[:k])
            if not name or name.group(1) in ("if", "for", "while", "switch", "return"):
                continue
            close = matching(self.flat, k, "(", ")")
            rest = re.match(r"[^;{]*", self.flat[close + 1 :])
            brace = close + 1 + rest.end()
            if brace >= len(self.flat) or self.flat[brace] != "{":
                continue  # a declaration
            # A lambda (`[&](const Properties& props) {`) belongs to the function around it.
            if re.search(r"\]\s*$", self.flat[:k]):
                continue
            end = matching(self.flat, brace, "{", "}")
            self.functions.append((name.group(1), brace, end))

    def reads_in(self, start, end):
        """(name, line) of the literal parameter names read between two offsets."""
        found = []
        flat = self.flat
        spans = []
        for m in re.finditer(r"\bprops\s*\.\s*" + READ_METHODS + r"\s*\(", flat[start:end]):
            spans.append(first_argument(flat, start + m.end()))
        for m in re.finditer(r"\(\s*props\s*,\s*", flat[start:end]):
            spans.append(first_argument(flat, start + m.end()))
        for a, b in spans:
            for lit in re.finditer(r'"((?:\\.|[^"\\\n])*)"', self.code[a:b]):
                found.append((lit.group(1), line_of(self.text, a + lit.start())))
        return found

    def calls_in(self, start, end):
        """Names of the functions called with `props` as their first argument."""
        names = set()
        for m in re.finditer(r"([A-Za-z_]\w*)\s*(<([^<>()]*)>)?\s*\(\s*props\s*[,)]", self.flat[start:end]):
            name = m.group(1)
            if name in ("make_shared", "make_unique") and m.group(3):
                name = m.group(3).split("::")[-1].strip()
            names.add(name)
        return names


class Block:
    def __init__(self, src, line, kind, names, helper=False):
        self.src, self.line, self.kind, self.names, self.helper = src, line, kind, names, helper
        self.description, self.mitsuba, self.uses, self.rows = [], [], [], []

    def where(self):
        return f"{self.src.rel}:{self.line}"


def parse_blocks(src, problems):
    blocks = []
    for m in re.finditer(r"/\*!(.*?)\*/", src.text, re.S):
        lines = m.group(1).split("\n")
        head = lines[0].split()
        first_line = line_of(src.text, m.start())
        if len(head) >= 3 and head[0] == "plugin":
            block = Block(src, first_line, head[1], head[2:])
            if block.kind not in KIND_TITLES:
                problems.append(f"{block.where()}: unknown plug-in kind '{block.kind}'")
        elif len(head) == 2 and head[0] == "parameters":
            block = Block(src, first_line, None, [head[1]], helper=True)
        else:
            problems.append(f"{src.rel}:{first_line}: a documentation block opens with 'plugin KIND NAME...' "
                            f"or 'parameters NAME'")
            continue
        section = "description"
        for offset, raw in enumerate(lines[1:], start=1):
            text = raw.strip()
            where = f"{src.rel}:{first_line + offset}"
            if text.startswith("|"):
                section = "rows"
                cells = [c.strip() for c in text.strip("|").split("|")]
                if cells[0] == "parameter" or set("".join(cells)) <= set("-: "):
                    continue  # the header row or a separator
                if len(cells) != len(COLUMNS):
                    problems.append(f"{where}: a parameter row has {len(cells)} cells, not {len(COLUMNS)} "
                                    f"({', '.join(COLUMNS)})")
                    continue
                block.rows.append((cells, first_line + offset))
            elif section == "rows":
                if text:
                    problems.append(f"{where}: text after the parameter table")
            elif text.startswith("uses:"):
                block.uses += [u.strip() for u in text[5:].split(",") if u.strip()]
                section = "uses"
            elif text.startswith("Mitsuba 3:"):
                block.mitsuba.append(text[len("Mitsuba 3:") :].strip())
                section = "mitsuba"
            elif section == "mitsuba":
                block.mitsuba.append(text)
            elif section == "description":
                block.description.append(text)
            elif text:
                problems.append(f"{where}: text after 'uses:'")
        blocks.append(block)
    return blocks


def load(src_dir):
    files = {}
    for root, dirs, names in os.walk(src_dir):
        dirs.sort()
        for name in sorted(names):
            if name.endswith((".cpp", ".h")):
                path = os.path.join(root, name)
                rel = os.path.relpath(path, os.path.dirname(os.path.abspath(src_dir)))
                files[rel] = SourceFile(path, rel)
    registry_path = os.path.join(src_dir, "builtin", "builtin_plugins.cpp")
    registry_rel = os.path.relpath(registry_path, os.path.dirname(os.path.abspath(src_dir)))
    registered = []  # (kind, name, factory, line)
    reg = files[registry_rel]
    for m in re.finditer(r'r\.add\(\s*"(\w+)"\s*,\s*"(\w+)"\s*,\s*(\w+)\s*\)', reg.code):
        registered.append((m.group(1), m.group(2), m.group(3), f"{registry_rel}:{line_of(reg.text, m.start())}"))
    definitions = {}  # function name -> [(file, start, end)]
    for f in files.values():
        for name, start, end in f.functions:
            definitions.setdefault(name, []).append((f, start, end))
    return files, registered, definitions


def reads_of(factory, definitions):
    """Every (name, file, line) read by `factory` and the functions it passes props to."""
    reads, seen = [], set()
    todo = [(factory, None)]
    while todo:
        name, caller_file = todo.pop()
        defs = definitions.get(name, [])
        local = [d for d in defs if d[0] is caller_file]
        for f, start, end in local or defs:
            if (f.rel, start) in seen:
                continue
            seen.add((f.rel, start))
            reads += [(n, f, line) for n, line in f.reads_in(start, end)]
            todo += [(callee, f) for callee in f.calls_in(start, end) if callee in definitions]
    return reads


def analyse(src_dir):
    problems = []
    files, registered, definitions = load(src_dir)
    blocks = []
    for f in files.values():
        blocks += parse_blocks(f, problems)
    plugin_blocks, helper_blocks = {}, {}
    for b in blocks:
        target = helper_blocks if b.helper else plugin_blocks
        for name in b.names:
            key = name if b.helper else (b.kind, name)
            if key in target:
                problems.append(f"{b.where()}: '{name}' is documented twice (also {target[key].where()})")
            target[key] = b
    registered_keys = {(kind, name) for kind, name, _, _ in registered}
    for key, b in plugin_blocks.items():
        if key not in registered_keys:
            problems.append(f"{b.where()}: {key[0]} '{key[1]}' is documented but not registered")
    used_helpers = set()
    plugins = []
    for kind, name, factory, where in registered:
        block = plugin_blocks.get((kind, name))
        if factory not in definitions:
            problems.append(f"{where}: the factory {factory} of {kind} '{name}' is not found")
            continue
        f, start, _ = definitions[factory][0]
        if block is None:
            problems.append(f"{f.rel}:{line_of(f.text, start)}: {kind} '{name}' has no documentation block "
                            f"(/*! plugin {kind} {name} ... */)")
            continue
        documented = {}  # parameter -> where documented
        for cells, line in block.rows:
            documented.setdefault(cells[0], f"{block.src.rel}:{line}")
        for u in block.uses:
            if u not in helper_blocks:
                problems.append(f"{block.where()}: '{u}' (uses:) names no 'parameters' block")
                continue
            used_helpers.add(u)
            for cells, line in helper_blocks[u].rows:
                documented.setdefault(cells[0], f"{helper_blocks[u].src.rel}:{line}")
        reads = reads_of(factory, definitions)
        read_names = {}
        for pname, rf, line in reads:
            # A literal ending in "_" is a prefix a number is appended to: documented as "prefix_N".
            read_names.setdefault(pname + "N" if pname.endswith("_") else pname, f"{rf.rel}:{line}")
        for pname, at in sorted(read_names.items(), key=lambda kv: kv[1]):
            if pname not in documented:
                problems.append(f"{at}: {kind} '{name}' reads parameter '{pname}', which its block "
                                f"({block.where()}) does not document")
        for pname, at in documented.items():
            if pname not in read_names:
                problems.append(f"{at}: {kind} '{name}' documents parameter '{pname}', which it never reads")
        plugins.append((kind, name, block, read_names))
    for name, b in helper_blocks.items():
        if name not in used_helpers:
            problems.append(f"{b.where()}: the parameters block '{name}' is used by no plug-in block")
    return plugins, helper_blocks, problems


def cell(text):
    return text if text else "—"


def render(plugins, helper_blocks):
    pages = {}
    by_kind = {}
    for kind, name, block, _ in plugins:
        by_kind.setdefault(kind, [])
        if block not in [b for _, b in by_kind[kind]]:
            by_kind[kind].append((name, block))
    for kind in KIND_ORDER:
        if kind not in by_kind:
            continue
        slug, title = KIND_TITLES[kind]
        out = [f"# {title}", "",
               f"The `<{kind}>` plug-ins, generated from the documentation block that opens each plug-in's source "
               f"file (`scripts/plugin-docs.py`). [The scene format](../reference.md) says how parameters are "
               f"written.", ""]
        for _, block in by_kind[kind]:
            out.append("## " + ", ".join(f"`{n}`" for n in block.names))
            out.append("")
            out.append(f"Source: `{block.src.rel}`.")
            out.append("")
            if block.description:
                out.append("\n".join(block.description).strip())
                out.append("")
            if block.mitsuba:
                out.append("**Mitsuba 3:** " + " ".join(block.mitsuba).strip())
                out.append("")
            rows = [cells for cells, _ in block.rows]
            for u in block.uses:
                if u in helper_blocks:
                    rows += [cells for cells, _ in helper_blocks[u].rows]
            if rows:
                out.append("| " + " | ".join(COLUMNS) + " |")
                out.append("|" + "|".join(" --- " for _ in COLUMNS) + "|")
                for cells in rows:
                    out.append("| " + " | ".join([f"`{cells[0]}`"] + [cell(c) for c in cells[1:]]) + " |")
            else:
                out.append("No parameters.")
            out.append("")
        pages[slug + ".md"] = "\n".join(out).rstrip() + "\n"
    return pages


def main(argv):
    args = argv[1:]
    if args[:1] == ["--reads"] and len(args) == 2:
        files, registered, definitions = load(args[1])
        for kind, name, factory, _ in registered:
            print(f"{kind} {name} ({factory}):")
            for pname, f, line in reads_of(factory, definitions):
                print(f"  {pname:36} {f.rel}:{line}")
        return 0
    check = args[:1] == ["--check"]
    if check:
        args = args[1:]
    if len(args) != 2:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    src_dir, out_dir = args
    plugins, helper_blocks, problems = analyse(src_dir)
    pages = render(plugins, helper_blocks)
    if check:
        existing = set(n for n in os.listdir(out_dir) if n.endswith(".md")) if os.path.isdir(out_dir) else set()
        for page, text in sorted(pages.items()):
            path = os.path.join(out_dir, page)
            try:
                with open(path, encoding="utf-8") as f:
                    current = f.read()
            except FileNotFoundError:
                current = None
            if current != text:
                problems.append(f"{path}: {'missing' if current is None else 'stale'}: "
                                f"regenerate it with scripts/plugin-docs.py {src_dir} {out_dir}")
        for page in sorted(existing - set(pages)):
            problems.append(f"{os.path.join(out_dir, page)}: no plug-in kind gives this page")
        for p in problems:
            print(p)
        count = sum(len(b.rows) for b in {id(b): b for _, _, b, _ in plugins}.values())
        count += sum(len(b.rows) for b in helper_blocks.values())
        if problems:
            print(f"{len(problems)} problem(s) in the plug-in documentation")
            return 1
        print(f"{len(plugins)} plug-ins documented ({count} parameter rows); {len(pages)} pages up to date")
        return 0
    for p in problems:
        print("warning: " + p, file=sys.stderr)
    os.makedirs(out_dir, exist_ok=True)
    for page, text in pages.items():
        with open(os.path.join(out_dir, page), "w", encoding="utf-8") as f:
            f.write(text)
    print(f"wrote {len(pages)} pages to {out_dir}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
