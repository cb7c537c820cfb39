#!/usr/bin/env python3
"""Import circles between the modules of a crate: each file's `crate::a::b` and `super::x` paths
(outside comments and test modules) become edges between modules cut at DEPTH path segments, and
every strongly connected component of more than one module is reported with its edges. Exits 1
when there is one. Usage: module-graph.py CRATE_SRC [DEPTH]"""
import os, re, sys
from collections import defaultdict

src = sys.argv[1]
depth = int(sys.argv[2]) if len(sys.argv) > 2 else 2

def module_of(path):
    rel = os.path.relpath(path, src)[:-3].split(os.sep)
    if rel[-1] == 'mod':
        rel = rel[:-1]
    if rel == ['lib'] or rel == ['main']:
        return None
    return tuple(rel)

mods = {}
for root, _, files in os.walk(src):
    for f in files:
        if f.endswith('.rs'):
            p = os.path.join(root, f)
            m = module_of(p)
            if m:
                mods[m] = p
known = set(mods)
def resolve(parts):
    # the longest known module prefix of a crate path
    for n in range(len(parts), 0, -1):
        if tuple(parts[:n]) in known:
            return tuple(parts[:n])
    return None

def cut(m):
    return m[:depth]

edges = defaultdict(set)
pat = re.compile(r'crate::((?:[a-z_][a-z0-9_]*::)*[a-z_][a-z0-9_]*)')
use_group = re.compile(r'use\s+crate::(\{[^;]*\}|[^;]*);', re.S)
for m, p in mods.items():
    text = open(p, encoding='utf-8').read()
    # drop test modules: they may import anything
    text = re.split(r'#\[cfg\(test\)\]\s*mod tests', text)[0]
    # comments and docs name modules without importing them
    text = re.sub(r'//[^\n]*', '', text)
    targets = set()
    for hit in pat.findall(text):
        r = resolve(hit.split('::'))
        if r: targets.add(r)
    for g in use_group.findall(text):
        if g.startswith('{'):
            for item in re.findall(r'([a-z_][a-z0-9_]*(?:::[a-z_][a-z0-9_]*)*)', g):
                r = resolve(item.split('::'))
                if r: targets.add(r)
    # `super::x` inside a folder
    for hit in re.findall(r'super::([a-z_][a-z0-9_]*)', text):
        parent = m[:-1]
        r = resolve(list(parent) + [hit])
        if r: targets.add(r)
    for t in targets:
        a, b = cut(m), cut(t)
        if a != b and not (b[:len(a)] == a or a[:len(b)] == b):
            edges[a].add(b)

# Tarjan
index = {}; low = {}; stack = []; on = set(); sccs = []; counter = [0]
nodes = set(edges) | {b for v in edges.values() for b in v}
sys.setrecursionlimit(10000)
def strong(v):
    index[v] = low[v] = counter[0]; counter[0] += 1
    stack.append(v); on.add(v)
    for w in edges.get(v, ()):
        if w not in index:
            strong(w); low[v] = min(low[v], low[w])
        elif w in on:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        comp = []
        while True:
            w = stack.pop(); on.discard(w); comp.append(w)
            if w == v: break
        if len(comp) > 1: sccs.append(comp)
for v in sorted(nodes):
    if v not in index: strong(v)
for c in sccs:
    names = sorted('::'.join(x) for x in c)
    print('circle:', ' ⇄ '.join(names))
    for a in c:
        for b in edges[a]:
            if b in c: print('   ', '::'.join(a), '→', '::'.join(b))
print(f'{len(sccs)} import circles among {len(nodes)} modules (depth {depth})')
sys.exit(1 if sccs else 0)
