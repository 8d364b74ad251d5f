#!/usr/bin/env python3
"""book/check_links.py BOOKDIR - every link of the built book resolves and
nothing is loaded from the network.

For every HTML page under BOOKDIR: each relative href and src names a file
that exists, and each #fragment an id of the page it points to; no src
attribute and no stylesheet link is an http:// or https:// address; no
stylesheet imports or points at one. Prints one line per page with a
problem, and "links: N passed, N failed" (one check per page and per
stylesheet).
"""
import glob
import os
import re
import sys
from html.parser import HTMLParser
from urllib.parse import unquote, urlsplit

REMOTE = re.compile(r"^(https?:)?//", re.I)


class Page(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids = set()
        self.refs = []  # (tag, attribute, value)

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if a.get("id"):
            self.ids.add(a["id"])
        if tag == "a" and a.get("name"):
            self.ids.add(a["name"])
        for key in ("href", "src", "poster", "data"):
            if a.get(key) is not None:
                kind = "stylesheet" if tag == "link" and "stylesheet" in (a.get("rel") or "") else tag
                self.refs.append((kind, key, a[key]))
        if a.get("srcset"):
            for part in a["srcset"].split(","):
                self.refs.append((tag, "srcset", part.strip().split(" ")[0]))


def parse(path, cache):
    if path not in cache:
        p = Page()
        with open(path, encoding="utf-8") as f:
            p.feed(f.read())
        cache[path] = p
    return cache[path]


def check_page(path, cache):
    problems = []
    page = parse(path, cache)
    for kind, key, value in page.refs:
        if REMOTE.match(value):
            if key != "href" or kind == "stylesheet":
                problems.append("%s %s= loads from the network: %s" % (kind, key, value))
            continue
        parts = urlsplit(value)
        if parts.scheme in ("mailto", "data"):
            continue
        if parts.scheme:
            problems.append("%s %s= has scheme %s: %s" % (kind, key, parts.scheme, value))
            continue
        target = path if not parts.path else os.path.normpath(
            os.path.join(os.path.dirname(path), unquote(parts.path)))
        if not os.path.isfile(target):
            problems.append("%s %s=%s: no file %s" % (kind, key, value, target))
            continue
        if parts.fragment and target.endswith(".html"):
            if unquote(parts.fragment) not in parse(target, cache).ids:
                problems.append("%s %s=%s: no id '%s' in %s"
                                % (kind, key, value, parts.fragment, os.path.basename(target)))
    return problems


def check_css(path):
    with open(path, encoding="utf-8") as f:
        css = f.read()
    bad = re.findall(r"(?:url\(\s*['\"]?|@import\s+['\"]?)((?:https?:)?//[^'\")\s]+)", css, re.I)
    return ["stylesheet loads from the network: " + u for u in bad]


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_links.py BOOKDIR")
    book = sys.argv[1]
    cache = {}
    passed = failed = 0
    pages = sorted(glob.glob(os.path.join(book, "**", "*.html"), recursive=True))
    sheets = sorted(glob.glob(os.path.join(book, "**", "*.css"), recursive=True))
    if not pages:
        print("FAIL  links: no HTML page in " + book)
        failed += 1
    for path in pages + sheets:
        problems = check_css(path) if path.endswith(".css") else check_page(path, cache)
        if problems:
            failed += 1
            for p in problems[:10]:
                print("FAIL  links %s: %s" % (os.path.relpath(path, book), p))
        else:
            passed += 1
    print("links: %d pages and stylesheets checked, %d internal references"
          % (len(pages) + len(sheets), sum(len(p.refs) for p in cache.values())))
    print("links: %d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
