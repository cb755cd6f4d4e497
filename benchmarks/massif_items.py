#!/usr/bin/env python3
"""The heap at the largest state of a massif run, item by item.

Usage: benchmarks/massif_items.py <massif.out> <DoFs> [--other]

Reads the tree of the largest heap snapshot from `ms_print` and gives
every allocation to the item named by the frame nearest to it on its call
stack (mesh, DoF handler, constraints, multigrid transfer, cell tables,
level and fine vectors of deal.II; Trilinos vectors by the nearest
function of this project). Prints MiB and bytes per DoF (the <DoFs> of
all fields) per item; --other also lists the larger allocations that no
rule names. Used for doc/scaling.md, "Memory" (where the heap goes at
its largest).
"""
import re
import subprocess
import sys

RULES = [
    ('mesh (Triangulation, p4est)',
     r'Triangulation|TriaObjects|TriaLevel|TriaFaces|libsc|p4est'),
    ('DoF handler (active and level DoFs)', r'DoFHandler'),
    ('constraints', r'AffineConstraints|MGConstrainedDoFs'),
    ('multigrid transfer', r'MGTransfer|MGLevelGlobalTransfer'),
    ('cell tables (Q1Cells)', r'Q1Cells'),
    ('level vectors (float)', r'la_parallel_vector_templates_functions<float'),
    ('distributed vectors (double)',
     r'la_parallel_vector_templates_functions<double'),
    ('Trilinos vectors', r'Epetra'),
]


def largest_snapshot(text):
    """The total and the tree of the detailed snapshot with most heap."""
    best = (0, '')
    for block in re.split(r'\n-{20,}\n', text):
        total = re.search(r'\(([\d,]+)B\) \(heap allocation functions\)', block)
        if total and int(total.group(1).replace(',', '')) > best[0]:
            best = (int(total.group(1).replace(',', '')), block)
    return best


def function_name(frame):
    """The frame without its address and its argument list."""
    frame = re.sub(r'^0x[0-9A-F]+: ', '', frame)
    depth = 0
    for k, c in enumerate(frame):
        if c == '<':
            depth += 1
        elif c == '>':
            depth -= 1
        elif c == '(' and depth == 0 and k > 0:
            location = re.search(r'\((\w+\.cc:\d+)\)$', frame)
            return frame[:k] + (f' ({location.group(1)})' if location else '')
    return frame


def main():
    text = subprocess.run(['ms_print', '--threshold=0.01', sys.argv[1]],
                          capture_output=True, text=True, check=True).stdout
    dofs = float(sys.argv[2])
    list_other = '--other' in sys.argv
    total, tree = largest_snapshot(text)
    nodes = []
    for line in tree.split('\n'):
        m = re.match(r'^([ |]*)->\s*[\d.]+% \(([\d,]+)B\) (.*)$', line)
        if m:
            nodes.append((len(m.group(1)) // 2,
                          int(m.group(2).replace(',', '')), m.group(3)))
    items = {}
    for i, (depth, size, frame) in enumerate(nodes):
        if i + 1 < len(nodes) and nodes[i + 1][0] > depth:
            continue  # not a leaf: its children carry the bytes
        # the call stack from the allocation outwards
        stack = [function_name(frame)]
        d = depth
        for j in range(i - 1, -1, -1):
            if nodes[j][0] < d:
                stack.append(function_name(nodes[j][2]))
                d = nodes[j][0]
        stack.reverse()
        item = 'other'
        for name in stack:
            hits = [rule for rule, rx in RULES if re.search(rx, name)]
            if hits:
                item = hits[0]
                break
        if item == 'Trilinos vectors':
            own = [name for name in stack if 'PhaseField::' in name]
            if own:
                item += ': ' + own[0]
        if item == 'other' and list_other and size > 200000:
            print(f'  other {size} B: ' + ' <- '.join(stack[:6]))
        items[item] = items.get(item, 0) + size
    print(f'largest heap state {total / 2**20:.1f} MiB = '
          f'{total / dofs:.0f} B per DoF')
    print(f'{"B/DoF":>7} {"MiB":>8}  item')
    for item, size in sorted(items.items(), key=lambda kv: -kv[1]):
        print(f'{size / dofs:7.1f} {size / 2**20:8.1f}  {item}')


if __name__ == '__main__':
    main()
