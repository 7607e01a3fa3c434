#!/usr/bin/env python3
"""Writes the seed corpora of the three sample fuzzers (corpus/*_sample_fuzz/):
CDR bytes of LaserScan, Odometry and LabeledScan samples laid out as
idl/scanfilter_types.idl defines them (little-endian plain CDR with its
4-byte encapsulation header), framed as sample_pipeline.hpp reads them
(2-byte little-endian length, then the sample). Run it after changing the IDL."""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


class Cdr:
    def __init__(self):
        self.b = bytearray()

    def align(self, n):
        while len(self.b) % n:
            self.b.append(0)

    def u32(self, v):
        self.align(4)
        self.b += struct.pack('<I', v)

    def i32(self, v):
        self.align(4)
        self.b += struct.pack('<i', v)

    def u64(self, v):
        self.align(8)
        self.b += struct.pack('<Q', v)

    def f32(self, v):
        self.align(4)
        self.b += struct.pack('<f', v)

    def f64(self, v):
        self.align(8)
        self.b += struct.pack('<d', v)

    def boolean(self, v):
        self.b.append(1 if v else 0)

    def string(self, s):
        data = s.encode() + b'\0'
        self.u32(len(data))
        self.b += data

    def seq(self, values, put):
        self.u32(len(values))
        for v in values:
            put(v)

    def sample(self):
        return b'\x00\x01\x00\x00' + bytes(self.b)  # CDR_LE encapsulation


def header(c, sec, nsec, frame):
    c.i32(sec)
    c.u32(nsec)
    c.string(frame)


def ranges(n, sec):
    # A room corner with a thin leg: jumps and shadows for the filters.
    out = []
    for i in range(n):
        r = 2.0 + 0.5 * math.sin(i / 3.0 + sec)
        if i == n // 2:
            r = 1.0
        if i % 11 == 10:
            r = float('nan')
        if i % 13 == 12:
            r = float('inf')
        out.append(r)
    return out


def laser_scan(sec, n=32):
    c = Cdr()
    header(c, sec, 500, 'laser')
    for v in (-1.5, 1.5, 3.0 / (n - 1), 0.0, 0.1, 0.05, 10.0):
        c.f32(v)
    c.seq(ranges(n, sec), c.f32)
    c.seq([100.0] * n, c.f32)
    return c.sample()


def odometry(sec, x):
    c = Cdr()
    header(c, sec, 250_000_000, 'odom')
    c.string('base_link')
    for v in (x, 0.5, 0.0, 0.0, 0.0, math.sin(0.1 * sec), math.cos(0.1 * sec)):
        c.f64(v)
    for _ in range(36):
        c.f64(0.0)
    for _ in range(6):
        c.f64(0.1)
    for _ in range(36):
        c.f64(0.0)
    return c.sample()


def labeled_scan(seq, n=48, labels=False, timing=True, source=False):
    c = Cdr()
    header(c, 100 + seq, 1000 * seq, 'map')
    c.u64(seq)
    for v in (0.1 * seq, 0.0, 0.02 * seq, 0.1, 0.0, 0.0):
        c.f64(v)
    c.boolean(seq % 2 == 1)
    for v in (0.5, -math.pi / 2, math.pi / (n - 1), 0.05, 8.0):
        c.f64(v)
    c.seq(ranges(n, seq), c.f64)
    c.seq([], c.f32)
    c.seq([i % 4 for i in range(n)] if labels else [], lambda v: c.b.append(v))
    def stage(name):
        c.string(name)
        c.i32(1)
        c.u32(2)
        c.i32(1)
        c.u32(3)
    c.seq(['scan_ingest'] if timing else [], stage)
    c.boolean(source)
    c.string('laser' if source else '')
    for v in (-1.5, 1.5, 0.01, 0.0, 0.1, 0.05, 10.0):
        c.f32(v)
    return c.sample()


def framed(samples):
    out = bytearray()
    for s in samples:
        out += struct.pack('<H', len(s)) + s
    return bytes(out)


def write(target, name, data):
    d = os.path.join(HERE, 'corpus', target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), 'wb') as f:
        f.write(data)


write('laser_scan_sample_fuzz', 'one', framed([laser_scan(1)]))
write('laser_scan_sample_fuzz', 'four', framed([laser_scan(s) for s in range(4)]))
write('odometry_sample_fuzz', 'three', framed([odometry(s, 0.1 * s) for s in range(3)]))
write('odometry_sample_fuzz', 'backwards', framed([odometry(5, 0.0), odometry(3, 1.0)]))
write('labeled_scan_sample_fuzz', 'one', framed([labeled_scan(0)]))
write('labeled_scan_sample_fuzz', 'five', framed([labeled_scan(s, labels=s > 2, source=s == 4) for s in range(5)]))
