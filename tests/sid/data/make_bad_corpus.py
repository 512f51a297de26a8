#!/usr/bin/env python3
# Generates minimal.sid and the damaged corpus bad/*.sid next to this script (run it after
# changing a case; the test reads the files, not this script).
# Each bad file starts with `expect: <line>: <kind>: <message fragment>` (free text before
# `part` is a header the reader skips).
import os, re
out = os.path.dirname(os.path.abspath(__file__))

def taylor(name, order, nrow, ncol, nq, structure, entries):
    ls = [name, f'    order        = {order}', f'    nrow         = {nrow}', f'    ncol         = {ncol}',
          f'    nq           = {nq}', '    nqn          = 0', f'    structure    = {structure}']
    ls += [f'    {e}' for e in entries]
    return ls + [f'end {name}']

def base():
    ls = ['part', 'new modal', 'refmod', '    mass           = 100.0', '    nelastq        = 1',
          '    ielastq(1) = Mode 1', 'end refmod', 'new frame', 'new node = 1', 'rframe = body ref']
    ls += taylor('origin', 1, 3, 1, 1, 3, ['m0( 3, 1)    = 10.0', 'm1( 1, 1, 1) = 1.0'])
    ls += taylor('phi', 0, 3, 1, 1, 3, ['m0( 1, 1)    = 1.0'])
    ls += taylor('psi', 0, 3, 1, 1, 3, ['m0( 2, 1)    = 0.1'])
    ls += taylor('AP', 0, 3, 3, 1, 1, ['m0( 1, 1)    = 1.0', 'm0( 2, 2)    = 1.0', 'm0( 3, 3)    = 1.0'])
    ls += ['end node', 'end frame']
    ls += taylor('mdCM', 0, 3, 1, 1, 3, ['m0( 3, 1)    = 500.0'])
    ls += taylor('J', 0, 3, 3, 1, 2, ['m0( 1, 1)    = 1.0e4', 'm0( 2, 2)    = 1.0e4', 'm0( 3, 3)    = 10.0'])
    ls += taylor('Ct', 0, 1, 3, 1, 3, ['m0( 1, 1)    = 30.0'])
    ls += taylor('Cr', 0, 1, 3, 1, 3, ['m0( 1, 2)    = 300.0'])
    ls += taylor('Me', 0, 1, 1, 1, 2, ['m0( 1, 1)    = 25.0'])
    ls += taylor('Ke', 0, 1, 1, 1, 2, ['m0( 1, 1)    = 2500.0'])
    return ls + ['end modal', 'end part']

def find(ls, text, start=0):
    for i in range(start, len(ls)):
        if ls[i] == text: return i
    raise KeyError(text)

def block_line(ls, name):
    return find(ls, name)

def in_block(ls, name, text):
    return find(ls, text, block_line(ls, name))

cases = []
def case(name, kind, fragment):
    def deco(f):
        cases.append((name, kind, fragment, f))
        return f
    return deco

def replace(ls, block, old, new):
    i = in_block(ls, block, old)
    ls[i] = new
    return i

def remove_block(ls, name):
    i = block_line(ls, name)
    j = find(ls, 'end ' + name, i)
    del ls[i:j + 1]
    return i

@case('syntax_missing_equals', 'syntax', 'expected `=` after the indices')
def _(ls): return replace(ls, 'origin', '    m0( 3, 1)    = 10.0', '    m0( 3, 1)    10.0')
@case('syntax_bad_index', 'syntax', 'expected an index')
def _(ls): return replace(ls, 'origin', '    m0( 3, 1)    = 10.0', '    m0( 3, x)    = 10.0')
@case('syntax_unclosed_index', 'syntax', 'expected `,` or `)`')
def _(ls): return replace(ls, 'origin', '    m0( 3, 1)    = 10.0', '    m0( 3, 1    = 10.0')
@case('syntax_not_a_number', 'syntax', "expected a number after `m0(1, 1) =`, found '30.0.1'")
def _(ls): return replace(ls, 'Ct', '    m0( 1, 1)    = 30.0', '    m0( 1, 1)    = 30.0.1')
@case('syntax_line_start', 'syntax', 'expected a name at the start of the line')
def _(ls):
    i = in_block(ls, 'J', '    m0( 2, 2)    = 1.0e4'); ls.insert(i, '    = 5'); return i
@case('syntax_end_extra', 'syntax', 'expected the end of the line')
def _(ls): return replace(ls, 'origin', 'end origin', 'end origin now')
@case('syntax_unclosed_block', 'syntax', 'block `phi` (line 22) is not closed: expected `end phi`')
def _(ls):
    i = in_block(ls, 'phi', 'end phi'); del ls[i]; return block_line(ls, 'psi')
@case('syntax_truncated', 'syntax', 'block `modal` is not closed: the file ends before `end modal`')
def _(ls):
    i = find(ls, 'end frame'); del ls[i + 1:]; return find(ls, 'new modal')
@case('syntax_stray_end', 'syntax', '`end foo` closes no open block')
def _(ls):
    i = in_block(ls, 'J', '    m0( 2, 2)    = 1.0e4'); ls.insert(i, 'end foo'); return i
@case('syntax_entry_without_indices', 'syntax', '`m0` needs indices')
def _(ls): return replace(ls, 'Ct', '    m0( 1, 1)    = 30.0', '    m0 = 30.0')
@case('no_part', 'missing-property', 'no line `part` in the file')
def _(ls): del ls[0]; return -1
@case('unknown_structure', 'invalid-value', 'unknown structure 5 of block `Me`')
def _(ls): return replace(ls, 'Me', '    structure    = 2', '    structure    = 5')
@case('index_out_of_range', 'invalid-value', 'row 4 is out of range 1..3 of block `origin`')
def _(ls): return replace(ls, 'origin', '    m0( 3, 1)    = 10.0', '    m0( 4, 1)    = 10.0')
@case('mode_out_of_range', 'invalid-value', 'mode 2 is out of range 1..1')
def _(ls): return replace(ls, 'origin', '    m1( 1, 1, 1) = 1.0', '    m1( 1, 1, 2) = 1.0')
@case('dimension_ct', 'invalid-value', 'block `Ct` is 1 x 2; it must be nq x 3 = 1 x 3')
def _(ls): replace(ls, 'Ct', '    ncol         = 3', '    ncol         = 2'); return block_line(ls, 'Ct')
@case('dimension_me', 'invalid-value', 'block `Me` is 2 x 2; it must be nq x nq = 1 x 1')
def _(ls):
    replace(ls, 'Me', '    ncol         = 1', '    ncol         = 2')
    replace(ls, 'Me', '    nrow         = 1', '    nrow         = 2'); return block_line(ls, 'Me')
@case('nq_mismatch', 'invalid-value', 'block `origin` has nq = 2 but the body has nelastq = 1')
def _(ls): return replace(ls, 'origin', '    nq           = 1', '    nq           = 2')
@case('non_finite', 'invalid-value', "m0(1, 1) of block `J` is 'nan': not a finite number")
def _(ls): return replace(ls, 'J', '    m0( 1, 1)    = 1.0e4', '    m0( 1, 1)    = nan')
@case('non_finite_overflow', 'invalid-value', "is '1e999': not a finite number")
def _(ls): return replace(ls, 'J', '    m0( 1, 1)    = 1.0e4', '    m0( 1, 1)    = 1e999')
@case('non_finite_mass', 'invalid-value', "the mass is 'inf'")
def _(ls): return replace(ls, 'refmod', '    mass           = 100.0', '    mass           = inf')
@case('negative_mass', 'invalid-value', "the mass is '-1': it must be a finite number >= 0")
def _(ls): return replace(ls, 'refmod', '    mass           = 100.0', '    mass           = -1')
@case('duplicate_block', 'invalid-value', '`Me` is given twice in this block (first at line 91)')
def _(ls):
    i = block_line(ls, 'Ke'); ls[i:i] = taylor('Me', 0, 1, 1, 1, 2, ['m0( 1, 1)    = 26.0']); return i
@case('duplicate_key', 'invalid-value', '`nrow` is given twice in this block')
def _(ls):
    i = in_block(ls, 'mdCM', '    ncol         = 1'); ls.insert(i, '    nrow         = 3'); return i
@case('duplicate_entry', 'invalid-value', 'm0(1, 1) of block `Ct` is given twice with different values')
def _(ls):
    i = in_block(ls, 'Ct', 'end Ct'); ls.insert(i, '    m0( 1, 1)    = 31.0'); return i
@case('symmetric_conflict', 'invalid-value', 'a symmetric block lists (i, j) and (j, i) once')
def _(ls):
    i = in_block(ls, 'J', 'end J'); ls[i:i] = ['    m0( 2, 1)    = 5.0', '    m0( 1, 2)    = 6.0']; return i + 1
@case('missing_refmod', 'missing-property', 'the body has no block `refmod`')
def _(ls): remove_block(ls, 'refmod'); return find(ls, 'new modal')
@case('missing_mass', 'missing-property', 'block `refmod` has no `mass`')
def _(ls): del ls[find(ls, '    mass           = 100.0')]; return find(ls, 'refmod')
@case('missing_nelastq', 'missing-property', 'block `refmod` has no `nelastq`')
def _(ls): del ls[find(ls, '    nelastq        = 1')]; return find(ls, 'refmod')
for blk in ['mdCM', 'J', 'Me', 'Ke']:
    def make(blk):
        @case('missing_' + blk.lower(), 'missing-property', f'the body has no block `{blk}`')
        def _(ls): remove_block(ls, blk); return find(ls, 'new modal')
    make(blk)
@case('missing_origin', 'missing-property', 'node 1 has no block `origin`')
def _(ls): remove_block(ls, 'origin'); return find(ls, 'new node = 1')
@case('missing_header_key', 'missing-property', 'block `Ke` has no `nrow`')
def _(ls): del ls[in_block(ls, 'Ke', '    nrow         = 1')]; return block_line(ls, 'Ke')
@case('header_not_integer', 'invalid-value', '`nrow` of block `mdCM` must be a whole number')
def _(ls): return replace(ls, 'mdCM', '    nrow         = 3', '    nrow         = 3.0')
@case('limit_nq', 'limit', 'more than 10000 modes')
def _(ls): return replace(ls, 'refmod', '    nelastq        = 1', '    nelastq        = 20000')
@case('limit_values', 'limit', 'block `Me` holds 36000000 numbers')
def _(ls):
    replace(ls, 'refmod', '    nelastq        = 1', '    nelastq        = 6000')
    del ls[find(ls, '    ielastq(1) = Mode 1')]
    i = find(ls, 'new frame'); j = find(ls, 'end frame'); del ls[i:j + 1]
    remove_block(ls, 'Ct'); remove_block(ls, 'Cr'); remove_block(ls, 'Ke')
    for blk in ['mdCM', 'J']: replace(ls, blk, '    nq           = 1', '    nq           = 0')
    i = block_line(ls, 'Me'); j = find(ls, 'end Me', i)
    ls[i:j + 1] = taylor('Me', 0, 6000, 6000, 6000, 2, [])
    return i
@case('order2', 'not-supported', 'block `Ke` has order 2')
def _(ls): return replace(ls, 'Ke', '    order        = 0', '    order        = 2')
@case('structure_diagonal_offdiagonal', 'invalid-value', 'lies outside the diagonal structure 1 of block `AP`')
def _(ls):
    i = in_block(ls, 'AP', 'end AP'); ls.insert(i, '    m0( 1, 2)    = 0.5'); return i
@case('m1_in_order0', 'invalid-value', 'block `phi` has order 0, so it has no first-order entries')
def _(ls):
    i = in_block(ls, 'phi', 'end phi'); ls.insert(i, '    m1( 1, 1, 1) = 1.0'); return i
@case('wrong_index_count', 'invalid-value', '`m0` takes 2 indices')
def _(ls): return replace(ls, 'Ct', '    m0( 1, 1)    = 30.0', '    m0( 1, 1, 1) = 30.0')
@case('duplicate_node_id', 'invalid-value', 'node 1 is given twice (first at line 10)')
def _(ls):
    i = find(ls, 'new node = 1'); j = find(ls, 'end node'); ls[j + 1:j + 1] = ls[i:j + 1]; return j + 1
@case('node_id_text', 'invalid-value', "a node needs a whole number: `new node = 1`, not 'tip'")
def _(ls): i = find(ls, 'new node = 1'); ls[i] = 'new node = tip'; return i
@case('symmetric_not_square', 'invalid-value', 'a symmetric block (structure 2) must be square')
def _(ls): return replace(ls, 'Cr', '    structure    = 3', '    structure    = 2')
@case('mode_name_out_of_range', 'invalid-value', '`ielastq` takes one index, the mode 1..1')
def _(ls):
    i = find(ls, '    ielastq(1) = Mode 1'); ls.insert(i + 1, '    ielastq(2) = Mode 2'); return i + 1

def write(path, lines):
    with open(path, 'w', newline='\n') as f: f.write('\n'.join(lines) + '\n')

write(os.path.join(out, 'minimal.sid'), base())
os.makedirs(os.path.join(out, 'bad'), exist_ok=True)
for f in os.listdir(os.path.join(out, 'bad')): os.remove(os.path.join(out, 'bad', f))
for name, kind, fragment, f in cases:
    ls = base()
    i = f(ls)
    line = 1 if i < 0 else i + 2  # +1 for 1-based, +1 for the expect line
    write(os.path.join(out, 'bad', name + '.sid'), [f'expect: {line}: {kind}: {fragment}'] + ls)
print(len(cases), 'cases')
