"""A question bank as an IMS QTI 1.2 package (a zip with ``imsmanifest.xml``), the
form Canvas (Classic Quizzes) and D2L import (Blackboard reads QTI 2.1, without
numeric questions: it gets an Upload Questions file instead, bank_blackboard).

One QTI file per problem: an ``<assessment>`` named after the problem whose one
section holds its items, so the system makes a quiz and a question bank of
that name. Each item asks one number (these systems' numeric question holds
one): a variant that asks several (two roots) gives one item per number, each
with the whole statement. An item is written as Canvas writes a
``numerical_question``: a ``response_str`` rendered as a decimal fill-in, and
a condition that scores 100 when the response equals the answer or lies in
[answer - error, answer + error], the error being the problem's tolerance;
the worked answer is the item's general feedback (``itemfeedback`` ident
``general_fb``). The element order is that of the QTI 1.2 ASI schema
(ims_qtiasiv1p2: itemmetadata, presentation, resprocessing, itemfeedback).
"""

from __future__ import annotations

import io
import zipfile
from collections.abc import Callable

from .bank import (
    Blank,
    Choice,
    ProblemBank,
    Variant,
    blank_prompt,
    choice_prompt,
    html_text,
    number_text,
    stable_uuid,
    xml_attr,
    xml_text,
)

QTI_NS = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2"
QTI_XSD = "http://www.imsglobal.org/xsd/ims_qtiasiv1p2p1.xsd"
CP_NS = "http://www.imsglobal.org/xsd/imscp_v1p1"
CP_XSD = "http://www.imsglobal.org/xsd/imscp_v1p1.xsd"
XSI = "http://www.w3.org/2001/XMLSchema-instance"
#: a fixed time for every zip entry, so the same export gives the same bytes
ZIP_TIME = (2000, 1, 1, 0, 0, 0)


def ident(*parts: object) -> str:
    """An identifier from the problem, variant and blank: ``g`` and 32 hex digits."""
    return "g" + stable_uuid(*parts).hex


def file_name(bank: ProblemBank) -> str:
    return f"{bank.slug}/{bank.slug}.xml"


def assessment(bank: ProblemBank) -> str:
    """The QTI file of one problem."""
    return (assessment_head(bank) + "".join(item + "\n" for variant in bank.variants
                                            for item in items(bank, variant))
            + ASSESSMENT_TAIL)


def assessment_head(bank: ProblemBank) -> str:
    """The QTI file of one problem up to its items."""
    return "\n".join([
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<questestinterop xmlns="{QTI_NS}" xmlns:xsi="{XSI}" '
        f'xsi:schemaLocation="{QTI_NS} {QTI_XSD}">',
        f'  <assessment ident="{ident(bank.id)}" title="{xml_attr(bank.name)}">',
        "    <qtimetadata>",
        _field("cc_maxattempts", "1"),
        "    </qtimetadata>",
        f'    <section ident="{ident(bank.id, "section")}" title="{xml_attr(bank.name)}">',
        ""])


#: the QTI file of one problem after its items
ASSESSMENT_TAIL = "    </section>\n  </assessment>\n</questestinterop>\n"


def items(bank: ProblemBank, variant: Variant) -> list[str]:
    """A variant's items: one per number asked, then one per word asked (``bank.size``
    must be known; its variants need not be held)."""
    return ([_item(bank, variant, blank) for blank in variant.blanks]
            + [_choice_item(bank, variant, choice) for choice in variant.choices])


def _field(label: str, entry: str, indent: str = "      ") -> str:
    return (f"{indent}<qtimetadatafield><fieldlabel>{xml_text(label)}</fieldlabel>"
            f"<fieldentry>{xml_text(entry)}</fieldentry></qtimetadatafield>")


def item_title(bank: ProblemBank, variant: Variant, blank: Blank | Choice) -> str:
    name = f"{bank.id} variant {variant.number}" if bank.size > 1 else bank.id
    return f"{name}: {blank.label}" if variant.asks > 1 else name


def _choice_item(bank: ProblemBank, variant: Variant, choice: Choice) -> str:
    """A word answer as a multiple-choice item (Canvas's multiple_choice_question): a
    response_lid rendered as choices, 100 for the solver's word."""
    idents = {word: f"c{n}" for n, word in enumerate(choice.choices, 1)}
    i = _INDENT
    labels = [f'{i}        <response_label ident="{idents[word]}"><material><mattext '
              f'texttype="text/plain">{xml_text(word)}</mattext></material></response_label>'
              for word in choice.choices]
    response = [f'{i}    <response_lid ident="response1" rcardinality="Single">',
                f"{i}      <render_choice>", *labels, f"{i}      </render_choice>",
                f"{i}    </response_lid>"]
    condition = [f'{i}        <varequal respident="response1">{idents[choice.answer]}</varequal>']
    return _item_frame(bank, variant, choice, "multiple_choice_question", [],
                       choice_prompt(choice), response, condition)


def _item(bank: ProblemBank, variant: Variant, blank: Blank) -> str:
    """A number asked as a numerical item: the answer, or anything within its width."""
    low = blank.value - blank.half_width
    high = blank.value + blank.half_width
    i = _INDENT
    response = [f'{i}    <response_str ident="response1" rcardinality="Single">',
                f'{i}      <render_fib fibtype="Decimal"><response_label ident="answer1"/>'
                "</render_fib>",
                f"{i}    </response_str>"]
    condition = [
        f"{i}        <or>",
        f'{i}          <varequal respident="response1">{number_text(blank.value)}</varequal>',
        f"{i}          <and>",
        f'{i}            <vargte respident="response1">{number_text(low)}</vargte>',
        f'{i}            <varlte respident="response1">{number_text(high)}</varlte>',
        f"{i}          </and>",
        f"{i}        </or>"]
    fields = [("gyro_unit", blank.unit), ("gyro_tolerance", blank.tolerance)]
    return _item_frame(bank, variant, blank, "numerical_question", fields,
                       blank_prompt(blank), response, condition)


_INDENT = "      "


def _item_frame(bank: ProblemBank, variant: Variant, asked: Blank | Choice,
                question_type: str, fields: list[tuple[str, str]], prompt: str,
                response: list[str], condition: list[str]) -> str:
    """What every item has around its response and the condition that scores it: the
    metadata, the statement and prompt, the worked answer as general feedback."""
    i = _INDENT
    text = variant.statement_html + f"<p>{html_text(prompt)}:</p>"
    metadata = [("question_type", question_type), ("points_possible", "1.0"),
                ("gyro_answer", asked.key), *fields]
    return "\n".join([
        f'{i}<item ident="{ident(bank.id, variant.number, asked.key)}" '
        f'title="{xml_attr(item_title(bank, variant, asked))}">',
        f"{i}  <itemmetadata>",
        f"{i}    <qtimetadata>",
        *[_field(label, entry, i + "      ") for label, entry in metadata],
        f"{i}    </qtimetadata>",
        f"{i}  </itemmetadata>",
        f"{i}  <presentation>",
        f'{i}    <material><mattext texttype="text/html">{xml_text(text)}</mattext></material>',
        *response,
        f"{i}  </presentation>",
        f"{i}  <resprocessing>",
        f"{i}    <outcomes>",
        f'{i}      <decvar maxvalue="100" minvalue="0" varname="SCORE" vartype="Decimal"/>',
        f"{i}    </outcomes>",
        f'{i}    <respcondition continue="Yes">',
        f"{i}      <conditionvar><other/></conditionvar>",
        f'{i}      <displayfeedback feedbacktype="Response" linkrefid="general_fb"/>',
        f"{i}    </respcondition>",
        f'{i}    <respcondition continue="No">',
        f"{i}      <conditionvar>",
        *condition,
        f"{i}      </conditionvar>",
        f'{i}      <setvar action="Set" varname="SCORE">100</setvar>',
        f"{i}    </respcondition>",
        f"{i}  </resprocessing>",
        f'{i}  <itemfeedback ident="general_fb">',
        f'{i}    <flow_mat><material><mattext texttype="text/html">'
        f"{xml_text(_feedback(variant))}</mattext></material></flow_mat>",
        f"{i}  </itemfeedback>",
        f"{i}</item>"])


def _feedback(variant: Variant) -> str:
    """The worked answer, and its picture: a file of the package beside the QTI file."""
    return variant.feedback_html + variant.figure_html(variant.figure_name)


def figures(bank: ProblemBank) -> list[tuple[str, bytes]]:
    """The package's picture files of one problem: (path in the zip, PNG)."""
    return [(f"{bank.slug}/{v.figure_name}", v.figure) for v in bank.variants if v.figure]


def manifest(banks: list[ProblemBank],
             pictures: Callable[[ProblemBank], list[str]] | None = None) -> str:
    """``imsmanifest.xml``: one resource (of type imsqti_xmlv1p2) per problem's file.
    ``pictures``: the paths of a problem's pictures (default: those of its variants)."""
    pictures = pictures or (lambda bank: [path for path, _ in figures(bank)])
    out = ['<?xml version="1.0" encoding="UTF-8"?>',
           f'<manifest identifier="{ident("manifest", *(b.id for b in banks))}" '
           f'xmlns="{CP_NS}" xmlns:xsi="{XSI}" xsi:schemaLocation="{CP_NS} {CP_XSD}">',
           "  <metadata>",
           "    <schema>IMS Content</schema>",
           "    <schemaversion>1.1.3</schemaversion>",
           "  </metadata>",
           "  <organizations/>",
           "  <resources>"]
    for bank in banks:
        href = file_name(bank)
        out += [f'    <resource identifier="{ident(bank.id, "resource")}" '
                f'type="imsqti_xmlv1p2" href="{xml_attr(href)}">',
                f'      <file href="{xml_attr(href)}"/>',
                *(f'      <file href="{xml_attr(path)}"/>' for path in pictures(bank)),
                "    </resource>"]
    out += ["  </resources>", "</manifest>"]
    return "\n".join(out) + "\n"


def package(banks: list[ProblemBank]) -> bytes:
    """The zip: ``imsmanifest.xml`` and one QTI file per problem (same bytes each time)."""
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        entries: list[tuple[str, str | bytes]] = [("imsmanifest.xml", manifest(banks))]
        for bank in banks:
            entries += [(file_name(bank), assessment(bank)), *figures(bank)]
        for name, data in entries:
            archive.writestr(entry(name), data.encode("utf-8") if isinstance(data, str) else data)
    return buffer.getvalue()


def entry(name: str) -> zipfile.ZipInfo:
    """A zip entry as the package writes each: a fixed time, deflated, mode 644."""
    info = zipfile.ZipInfo(name, date_time=ZIP_TIME)
    info.compress_type = zipfile.ZIP_DEFLATED
    info.external_attr = 0o644 << 16
    return info
