// The Stage menu's marks: a ✓ before each stage whose last Check passed on
// the student's work in the page, a ✗ where it failed, nothing where it was
// never checked (the verdicts are kept with the work: my_work.ts).
export function markStages(select: HTMLSelectElement, verdict: (stageId: string) => boolean | undefined): void {
  for (const o of select.options) {
    o.dataset.label ??= o.text;
    const v = verdict(o.value);
    o.text = v === undefined ? o.dataset.label : `${v ? '✓' : '✗'} ${o.dataset.label}`;
  }
}
