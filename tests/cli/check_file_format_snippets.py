#!/usr/bin/env python3
"""check_file_format_snippets.py FILE_FORMAT_MD FRAMES_H5...

Runs every Python snippet of docs/file-format.md on each frames file (its "frames.h5"
replaced by the file), so that the page never shows a dataset that does not exist, and
checks the shapes the snippet's comments give.
"""
import re
import sys

page, files = sys.argv[1], sys.argv[2:]
snippets = re.findall(r"```python\n(.*?)```", open(page).read(), re.S)
assert snippets, f"{page}: no Python snippet found"
for path in files:
    for k, code in enumerate(snippets):
        scope = {}
        try:
            exec(code.replace('"frames.h5"', repr(path)), scope)
        except Exception as e:
            sys.exit(f"FAIL: snippet {k} of {page} on {path}: {type(e).__name__}: {e}")
        if "x" in scope:
            n, d = scope["x"].shape
            assert scope["r"].shape == (n,), f"radius {scope['r'].shape}, positions {scope['x'].shape}"
            if "f_n" in scope:
                assert scope["f_n"].shape == (len(scope["pairs"][0]), d), f"normal force {scope['f_n'].shape}"
        contacts = "with contacts" if "f_n" in scope else "without contacts"
        print(f"snippet {k} of {page} ran on {path} ({contacts})")
