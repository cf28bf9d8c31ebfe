"""The printed size of the text in a PDF's figures, read from its content streams (zlib only).

A matplotlib figure is included by pdfTeX as a Form XObject scaled to the width that
\\includegraphics asks for. The size a reader sees is the font size of the text operator (``Tf``)
times the scale of the text matrix, of the figure's own transformations and of its placement on the
page; mathtext exponents and subscripts are separate text runs at a smaller ``Tf``.
"""
from __future__ import annotations

import math
import re
import zlib

OBJ = re.compile(rb"(\d+)\s+(\d+)\s+obj\b")
REF = rb"(\d+)\s+0\s+R"


def _stream_bytes(data: bytes, start: int) -> tuple[bytes, bytes]:
    """The dictionary text and the raw stream of the object whose body starts at ``start``."""
    end = data.find(b"endobj", start)
    body = data[start:end]
    m = re.search(rb"stream\r?\n", body)
    if not m:
        return body, b""
    stop = body.rfind(b"endstream")
    return body[:m.start()], body[m.end():stop]


class Pdf:
    """Objects of a PDF file, with object streams unpacked (what pdfTeX writes)."""

    def __init__(self, path):
        data = path if isinstance(path, bytes) else open(path, "rb").read()
        self.objects: dict[int, tuple[bytes, bytes]] = {}
        for m in OBJ.finditer(data):
            self.objects[int(m.group(1))] = _stream_bytes(data, m.end())
        for number, (head, raw) in list(self.objects.items()):
            if b"/ObjStm" not in head:
                continue
            text = self._decode(head, raw)
            first = int(re.search(rb"/First\s+(\d+)", head).group(1))
            count = int(re.search(rb"/N\s+(\d+)", head).group(1))
            nums = [int(x) for x in text[:first].split()]
            offsets = [(nums[2 * i], nums[2 * i + 1]) for i in range(count)]
            for i, (obj, off) in enumerate(offsets):
                stop = offsets[i + 1][1] if i + 1 < count else len(text) - first
                self.objects.setdefault(obj, (text[first + off:first + stop], b""))

    @staticmethod
    def _decode(head: bytes, raw: bytes) -> bytes:
        return zlib.decompress(raw) if b"/FlateDecode" in head else raw

    def head(self, number: int) -> bytes:
        return self.objects[number][0]

    def stream(self, number: int) -> bytes:
        head, raw = self.objects[number]
        return self._decode(head, raw)

    def resolve_dict(self, text: bytes, key: bytes) -> bytes:
        """The value of ``key`` in a dictionary text, following one indirect reference."""
        m = re.search(rb"/" + key + rb"\s*" + REF, text)
        if m:
            return self.head(int(m.group(1)))
        m = re.search(rb"/" + key + rb"\s*<<", text)
        if not m:
            return b""
        depth, i = 0, m.end() - 2
        while i < len(text):
            if text[i:i + 2] == b"<<":
                depth, i = depth + 1, i + 2
            elif text[i:i + 2] == b">>":
                depth, i = depth - 1, i + 2
                if depth == 0:
                    return text[m.end() - 2:i]
            else:
                i += 1
        return b""

    def pages(self) -> list[int]:
        catalog = next(h for h, _ in self.objects.values() if re.search(rb"/Type\s*/Catalog", h))
        out: list[int] = []

        def walk(number: int) -> None:
            head = self.head(number)
            kids = re.search(rb"/Kids\s*\[([^\]]*)\]", head)
            if kids and b"/Type/Pages" in head.replace(b" ", b""):
                for k in re.findall(REF, kids.group(1)):
                    walk(int(k))
            else:
                out.append(number)

        walk(int(re.search(rb"/Pages\s*" + REF, catalog).group(1)))
        return out


TOKEN = re.compile(rb"\((?:\\.|[^\\)])*\)|<[0-9A-Fa-f\s]*>|/[^\s/\[\]()<>{}%]+|\[|\]|<<|>>|"
                   rb"[-+]?(?:\d+\.?\d*|\.\d+)|[A-Za-z'\"*]+\d*\*?", re.S)


def _scale(m: list[float]) -> float:
    return math.sqrt(abs(m[0] * m[3] - m[1] * m[2]))


def text_runs(pdf: Pdf, content: bytes, resources: bytes, scale: float, figure: str | None, out: list):
    """Append (figure, printed size, text) for every text run in ``content``."""
    stack, ctm = [], scale
    tm, fs, operands, xobjects = 1.0, 0.0, [], None
    nested = 0
    for tok in TOKEN.findall(content):
        if tok.startswith(b"(") and tok.endswith(b")") and nested == 0:
            operands.append(tok)
        elif tok in (b"[", b"<<"):
            nested += 1
            operands.append(tok)
        elif tok in (b"]", b">>"):
            nested -= 1
            operands.append(tok)
        elif nested or tok[:1] in b"/<(" or re.fullmatch(rb"[-+]?(?:\d+\.?\d*|\.\d+)", tok):
            operands.append(tok)
        else:
            op = tok
            nums = [float(x) for x in operands if re.fullmatch(rb"[-+]?(?:\d+\.?\d*|\.\d+)", x)]
            if op == b"q":
                stack.append(ctm)
            elif op == b"Q" and stack:
                ctm = stack.pop()
            elif op == b"cm" and len(nums) >= 6:
                ctm *= _scale(nums[-6:])
            elif op == b"BT":
                tm = 1.0
            elif op == b"Tm" and len(nums) >= 6:
                tm = _scale(nums[-6:])
            elif op == b"Tf" and nums:
                fs = nums[-1]
            elif op in (b"Tj", b"TJ", b"'", b'"') and figure is not None:
                text = b"".join(re.findall(rb"\(((?:\\.|[^\\)])*)\)", b" ".join(operands)))
                out.append((figure, fs * tm * ctm, text.decode("latin1")))
            elif op == b"Do" and operands:
                name = operands[-1][1:]
                if xobjects is None:
                    xobjects = pdf.resolve_dict(resources, b"XObject")
                m = re.search(rb"/" + re.escape(name) + rb"\s*" + REF, xobjects)
                if m:
                    number = int(m.group(1))
                    head = pdf.head(number)
                    if b"/Form" in head:
                        matrix = re.search(rb"/Matrix\s*\[([^\]]*)\]", head)
                        s = _scale([float(x) for x in matrix.group(1).split()]) if matrix else 1.0
                        label = figure or f"form {number}"
                        res = pdf.resolve_dict(head, b"Resources")
                        text_runs(pdf, pdf.stream(number), res, ctm * s, label, out)
            operands = []
    return out


def measure(path, inside_forms: bool = True) -> list[tuple[int, str, float, str]]:
    """(page, figure, printed size in pt, text) of every text run inside an included figure."""
    pdf = Pdf(path)
    top = None if inside_forms else "page"
    rows = []
    for page_no, number in enumerate(pdf.pages(), start=1):
        head = pdf.head(number)
        contents = re.search(rb"/Contents\s*(\[[^\]]*\]|" + REF + rb")", head)
        refs = [int(x) for x in re.findall(REF, contents.group(1))] if contents else []
        content = b"\n".join(pdf.stream(r) for r in refs)
        resources = pdf.resolve_dict(head, b"Resources")
        for figure, size, text in text_runs(pdf, content, resources, 1.0, top, []):
            if text.strip():
                rows.append((page_no, figure, size, text))
    return rows


