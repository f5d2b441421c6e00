#!/usr/bin/env python3
"""The note a student edition's README.md opens with, after its title
(scripts/student-edition.sh runs it on the edition's copy):

    scripts/edition-readme.py README.md WITH_REFERENCE(0|1)
"""
import sys

path, with_reference = sys.argv[1], sys.argv[2] == '1'
text = open(path, encoding='utf-8').read()
if with_reference:
    model = ("> The CPU reference's C++ is in it (`app/reference/`, the units' `probes.cpp`), so\n"
             "> `./raylab render --cpu` and asking a pixel work.\n")
else:
    model = ("> Nor is the model in any other language: the checker's expected values are data\n"
             "> recorded by your instructor's copy (each unit's `probes.json`, `recorded/`), and\n"
             "> `./raylab render --cpu`, asking a pixel and the bench's error columns say that\n"
             "> they need the CPU reference, which is not in this copy.\n")
note = ("> **Student edition.** This copy of raylab has no answers: no exercise's\n"
        "> `solution.glsl`, `mutants/` or `alternatives/` in `course/`, no `solutions/`,\n"
        "> and only the `unit` tests.\n" + model +
        "> `./raylab render`, `view`, `record` and `bench` run\n"
        "> your files in `exercises/` (in `view`, a file missing from an `--impl`\n"
        "> folder is the shipped stub), and `./raylab check` checks each exercise with your own\n"
        "> files for the others: its image step waits until every exercise passes its\n"
        "> probes ([docs/exercises/README.md](docs/exercises/README.md)). Documents\n"
        "> that mention `solutions/`, the solutions, the mutants, the reference's sources,\n"
        "> the tests of labels other than `unit` (`scripts/test.sh` runs only those here)\n"
        "> or `scripts/student-edition.sh` describe the instructor's repository, where\n"
        "> grading runs.\n\n")
title_end = text.index('\n\n') + 2
open(path, 'w', encoding='utf-8').write(text[:title_end] + note + text[title_end:])
