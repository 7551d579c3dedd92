"""The `[document]` table of every case kind: who hands the work in and to whom — the title page
of the записка (ГОСТ 7.32-2017, section 6.1) and the title block of a drawing sheet (ГОСТ 2.104,
form 1). Every field is optional: a blank stays blank on the page, to be written by hand.

    [document]
    student = "Иванов И. И."
    group = "МТ-301"
    teacher = "Петров П. П."
    university = "МГТУ им. Н. Э. Баумана"
    department = "Кафедра теории механизмов и машин"
    designation = "ТММ.КП.00.01"
    city = "Москва"
    year = 2026
"""
from __future__ import annotations

from typing import Annotated

from pydantic import Field

from flywheel.io.schema import StrictModel, text_field, within

#: the designation a sheet and a записка carry when the case gives none (ГОСТ 2.201 style)
DEFAULT_DESIGNATION = "ТММ.КП.00.01"


class DocumentSpec(StrictModel):
    """Names for the title page of the записка and the title block of the drawing sheets."""

    student: str = text_field(description="the student (Разраб.), e.g. 'Иванов И. И.'")
    group: str = text_field(description="the student's group, e.g. 'МТ-301'")
    teacher: str = text_field(description="the teacher who checks the project (Пров.)")
    university: str = text_field(description="the university (organisation line)")
    department: str = text_field(description="the department (кафедра)")
    ministry: str = text_field(description="the ministry line of the title page, if any")
    designation: str = text_field(description="the document's designation (обозначение); "
                                              f"default {DEFAULT_DESIGNATION}")
    tech_control: str = text_field(description="Т. контр. of the title block")
    norm_control: str = text_field(description="Н. контр. of the title block")
    approved: str = text_field(description="Утв. of the title block")
    city: str = text_field(description="the city of the title page")
    year: Annotated[int, within(1900, 2200)] | None = Field(
        None, description="the year of the title page; default: none (left blank)")
    margin_right_mm: Annotated[float, within(5.0, 30.0, "mm")] = Field(
        10.0, description="the записка's right margin [mm] (ГОСТ 7.32-2017: 10; some "
                          "departments ask 15)")

    @property
    def designation_or_default(self) -> str:
        """The designation to print: the case's, else DEFAULT_DESIGNATION."""
        return self.designation or DEFAULT_DESIGNATION
