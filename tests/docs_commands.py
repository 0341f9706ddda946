#!/usr/bin/env python3
"""The commands the documentation shows, for tests/docs_commands.sh.

  docs_commands.py extract ROOT NAME=PATH...
      One line per command of one of the programs NAME (PATH: the program in the build tree)
      in README.md, every README.md below ROOT and docs/*.md:
          WHERE <tab> KIND <tab> MODE <tab> WORDS
      WHERE is file:line, KIND where it was written (block: a fenced shell block; table: the
      `command` column of a table; prose: a code span in the text), WORDS the command as a
      shell-quoted argv, the program as PATH and the placeholders (WALL, DIR, N, model.glb...)
      replaced by real values that exist in the folder the test runs them from. MODE says how
      to check it:
          run    run it as written: a usage error (exit 2) fails
          mpi    a command mpirun (or scripts/cluster.sh) starts: run the program alone with its
                 arguments, where it stops saying it was not started by mpirun
          help   the names of subcommands in a table (`lightning2_emu route/sequence`): each
                 must be one of the program's (its --help lists it)
          words  a fragment in the text: every option it names must be one the program (and
                 subcommand) takes, and it must give no more positional arguments than those
      Identical commands are listed once, with every place that shows them.

  docs_commands.py check-words NAME=PATH...
      Reads WHERE <tab> WORDS lines on stdin and checks the words of each against the program's
      --help (as MODE words above): prints "ok   WHERE: ..." or "FAIL WHERE: ...", exits 1 when
      any failed.
"""

import glob
import os
import re
import shlex
import subprocess
import sys

# Words that stand for something the reader supplies, and what the test gives instead, in
# the folder the commands run in (tests/docs_commands.sh makes what they name). Looked up
# first by the option before the word, then by the word alone.
WALL = "walls/kd-2x2.toml"
BY_OPTION = {
    ("--displays-from", "DIR"): "out/default-wall/frame-9",  # what scripts/main.sh wrote
    ("--displays", "..."): "640x480,640x480,640x480,640x480",
    ("--pipeservers", "N"): "4",
    ("--content", "FILE"): "huge.tif",
}
BY_WORD = {
    "WALL": WALL, "W": WALL, "WALL.toml": WALL, "W.toml": WALL, "my-wall.toml": WALL,
    "row.toml": WALL,  # the README's example wall, written by the reader
    "DIR": "out/dir", "OUT": "out/dir", "N": "2", "I": "0", "K": "1", "K+1": "2", "S": "mesh",
    "model.glb": "{root}/data/bunny.ply",  # any model Assimp reads
    "frame.png": "out/row-scan/scanout-0.png",  # a scanned-out frame
    "/dev/pts/N": "{pty}", "/dev/pts/7": "{pty}", "/dev/ttyUSB0": "{pty}",  # a serial line
}
# Words that wrap a command of ours: the program is the first word after them that names one.
WRAPPERS = {"xvfb-run": "run", "nice": "run", "env": "run", "timeout": "run", "mpirun": "mpi",
            "cluster.sh": "mpi"}
SHELL_LANGUAGES = {"", "sh", "bash", "shell", "console"}


def doc_files(root):
    found = [os.path.join(root, "README.md")]
    for here, folders, files in os.walk(root):
        folders[:] = sorted(f for f in folders if not f.startswith((".", "build")))
        if here != root and "README.md" in files:
            found.append(os.path.join(here, "README.md"))
    found += sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    return found


def split_words(text, operators):
    """Shell words of `text` (comments dropped); with `operators`, only those before the first
    pipe, redirection, `;` or `&&`. None when the text is not shell (an unclosed quote)."""
    try:
        lexer = shlex.shlex(text, posix=True, punctuation_chars="|&;<>" if operators else "")
        lexer.whitespace_split = True
        lexer.commenters = "#"
        words = list(lexer)
    except ValueError:
        return None
    if operators:
        for i, w in enumerate(words):
            if w and set(w) <= set("|&;<>"):
                return words[:i]
    return words


def program_of(words, programs):
    """(index of the program's word, mode) or None."""
    i = 0
    while i < len(words) and re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*=.*", words[i]):
        i += 1  # VAR=value before the command
    if i >= len(words):
        return None
    first = os.path.basename(words[i])
    if first in programs:
        return i, "run"
    if first in WRAPPERS:
        for j in range(i + 1, len(words)):
            if os.path.basename(words[j]) in programs and not words[j].startswith("-"):
                return j, WRAPPERS[first]
    return None


def commands_in_blocks(path, lines):
    """(line number, text) of every command line of the fenced shell blocks."""
    fence, language, pending, start = None, None, "", 0
    for number, line in enumerate(lines, 1):
        opening = re.match(r"\s*(```+|~~~+)\s*([\w+-]*)", line)
        if fence is None:
            if opening:
                fence, language = opening.group(1), opening.group(2).lower()
            continue
        if line.strip().startswith(fence):
            fence = None
            continue
        if language not in SHELL_LANGUAGES:
            continue
        if not pending:
            start = number
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        yield start, pending + line
        pending = ""


def table_cells(line):
    """The cells of a table row, `|` inside code spans kept."""
    cells, cell, in_code = [], "", False
    for c in line.strip().strip("|"):
        if c == "`":
            in_code = not in_code
        if c == "|" and not in_code:
            cells.append(cell)
            cell = ""
        else:
            cell += c
    cells.append(cell)
    return [c.strip() for c in cells]


def spans_in_text(lines):
    """(line number, span, kind) of every code span outside fenced blocks: table for the
    `command` column of a table, prose for the rest."""
    text_lines = []
    fence = None
    for line in lines:  # fenced blocks blanked, line numbers kept
        opening = re.match(r"\s*(```+|~~~+)", line)
        if fence is None and opening:
            fence = opening.group(1)
            text_lines.append("")
        elif fence is not None:
            if line.strip().startswith(fence):
                fence = None
            text_lines.append("")
        else:
            text_lines.append(line)
    command_column = None
    table_spans = set()
    for number, line in enumerate(text_lines, 1):
        if not line.lstrip().startswith("|"):
            command_column = None
            continue
        cells = table_cells(line)
        if command_column is None:
            lowered = [c.lower() for c in cells]
            command_column = lowered.index("command") if "command" in lowered else -1
            continue
        if command_column < 0 or command_column >= len(cells) or set(cells[0]) <= set("-: "):
            continue
        for span in re.findall(r"`([^`]+)`", cells[command_column]):
            table_spans.add((number, span))
            yield number, span, "table"
    text = "\n".join(text_lines)
    for m in re.finditer(r"`([^`]+)`", text):
        number = text.count("\n", 0, m.start()) + 1
        span = " ".join(m.group(1).split())
        if (number, m.group(1)) not in table_spans:
            yield number, span, "prose"


def looks_like_output(words):
    """A message quoted in the text (`pipeserver 1 (pid 4242) killed ...`), not a command."""
    return any(re.search(r"[()]|[:,;]$", w) for w in words[1:]) or words[0].endswith(":")


def substitute(words, programs, root):
    """The program's argv with the placeholders replaced; brackets of optional parts dropped."""
    out = []
    for w in words:
        w = re.sub(r"^\[|\](\.\.\.)?$", "", w)  # [--entry NAME]...: an optional part
        if not w:
            continue
        previous = out[-1] if out else ""
        w = BY_OPTION.get((previous, w), BY_WORD.get(w, w))
        if w == "...":
            continue  # "and so on": nothing to give
        w = re.sub(r"^\$PWD/|^\$\{PWD\}/|^~/\.local/share/lightning2/", "", w)
        if "/" in w and os.path.basename(w) in programs:
            w = programs[os.path.basename(w)]  # a path to one of the programs, as built
        out.append(w.replace("{root}", root))
    return out


def fewer_frames(words):
    """`l2wall run` renders at most 3 frames (more than any --keep asks): the check is the
    command line, not the run's length."""
    if os.path.basename(words[0]) != "l2wall" or words[1:2] != ["run"]:
        return words
    keep = 0
    for i, w in enumerate(words[:-1]):
        if w == "--keep" and words[i + 1].isdigit():
            keep = int(words[i + 1])
    for i, w in enumerate(words[:-1]):
        if w == "--frames" and words[i + 1].isdigit():
            words[i + 1] = str(min(int(words[i + 1]), max(3, keep + 1)))
    return words


def extract(root, programs):
    records = {}  # (mode, words) -> [where, kind]
    order = []

    def add(where, kind, mode, words):
        key = (mode, shlex.join(words))
        if key in records:
            records[key][0] += "," + where
        else:
            records[key] = [where, kind]
            order.append(key)

    for path in doc_files(root):
        with open(path, encoding="utf-8") as f:
            lines = f.read().split("\n")
        name = os.path.relpath(path, root)
        found = [(n, text, "block") for n, text in commands_in_blocks(path, lines)]
        found += list(spans_in_text(lines))
        for number, text, kind in found:
            words = split_words(text, kind == "block")
            if not words:
                continue
            located = program_of(words, programs)
            if located is None or looks_like_output(words[located[0]:]):
                continue
            start, mode = located
            words = words[start:]
            if kind != "block" and len(words) > 1 and "/" in words[1] and \
                    re.fullmatch(r"[a-z-]+(/[a-z-]+)+", words[1]):
                # `strip_headers encode/ext/decode/dump`: the subcommands' names
                for sub in words[1].split("/"):
                    add(f"{name}:{number}", kind, "help", [programs[os.path.basename(words[0])], sub])
                continue
            if kind == "prose":  # checked as written, placeholders and all
                argv = [re.sub(r"^\[|\](\.\.\.)?$", "", w) for w in words]
                argv[0] = programs[os.path.basename(words[0])]
                add(f"{name}:{number}", kind, "words", [w for w in argv if w])
            else:
                argv = substitute(words, programs, root)
                argv[0] = programs[os.path.basename(words[0])]
                add(f"{name}:{number}", kind, mode, fewer_frames(argv))
    for key in order:
        where, kind = records[key]
        print(f"{where}\t{kind}\t{key[0]}\t{key[1]}")


# --- the words of a command against the program's --help ---------------------------------------

HELP_CACHE = {}


def help_of(argv):
    key = tuple(argv)
    if key not in HELP_CACHE:
        run = subprocess.run(argv + ["--help"], capture_output=True, text=True, timeout=60)
        HELP_CACHE[key] = run.stdout if run.returncode == 0 else None
    return HELP_CACHE[key]


def parse_help(text):
    """(options: name -> takes a value (0 no, 1 one, 2 many), positionals: count or None for
    any number, subcommands)."""
    options, positionals, subcommands, section = {}, 0, set(), None
    for line in text.split("\n"):
        if re.match(r"^\S.*:$|^\[Option Group:", line):  # Options:, [Option Group: live]
            section = line.rstrip(":").strip().lower()
            continue
        entry = re.match(r"^  (?:  )?(\S.*?)(?:\s{2,}|$)", line)  # 4 spaces: an option group's
        if not entry:
            continue
        head = entry.group(1)
        if section == "subcommands":
            subcommands.add(head.split()[0])
        elif section == "positionals":
            positionals = None if positionals is None or " ..." in head else positionals + 1
        elif head.startswith("-"):
            names, _, kind = head.partition(" ")
            kind = re.sub(r"\s*(Excludes|Needs):.*", "", kind)
            takes = 0 if not kind else 2 if kind.endswith(" ...") else 1
            for n in names.split(","):
                options[n] = takes
    return options, positionals, subcommands


def check_words(argv):
    """None when the words fit the program's --help, else why not."""
    program, words = argv[0], argv[1:]
    command = [program]
    text = help_of(command)
    if text is None:
        return f"{' '.join(command)} --help failed"
    options, positionals, subcommands = parse_help(text)
    given = 0
    i = 0
    while i < len(words):
        w = words[i]
        i += 1
        if w in ("|",) or re.fullmatch(r"[|.]+", w):
            continue
        if not w.startswith("-") or w == "-":
            if given == 0 and w in subcommands:
                command.append(w)
                text = help_of(command)
                if text is None:
                    return f"{' '.join(command)} --help failed"
                options, positionals, subcommands = parse_help(text)
                continue
            given += 1
            if positionals is not None and given > positionals:
                name = " ".join(os.path.basename(c) if n == 0 else c for n, c in enumerate(command))
                return (f"'{w}': {name} takes {positionals} positional argument"
                        f"{'' if positionals == 1 else 's'} (an option's value written after a flag?)")
            continue
        if w == "--":
            positionals = None
            continue
        name, has_value, _ = w.partition("=")
        if name not in options:
            which = " ".join(os.path.basename(c) if n == 0 else c for n, c in enumerate(command))
            return f"{name}: not an option of {which}"
        if options[name] == 1 and not has_value and i < len(words) and \
                not words[i].startswith("--"):
            i += 1  # its value
        elif options[name] == 2 and not has_value:
            while i < len(words) and not words[i].startswith("-"):
                i += 1
    return None


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "extract":
        root = os.path.abspath(sys.argv[2])
        programs = dict(a.split("=", 1) for a in sys.argv[3:])
        extract(root, programs)
        return 0
    if len(sys.argv) >= 2 and sys.argv[1] == "check-words":
        failed = 0
        for line in sys.stdin:
            where, words = line.rstrip("\n").split("\t", 1)
            argv = shlex.split(words)
            why = check_words(argv)
            shown = " ".join([os.path.basename(argv[0])] + argv[1:])
            if why:
                print(f"FAIL {where}: {shown}: {why}")
                failed = 1
            else:
                print(f"ok   {where}: {shown}: options and arguments as --help has them")
        return failed
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
