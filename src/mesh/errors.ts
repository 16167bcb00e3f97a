/** One problem found in a cage, with the 1-based source line (0 if not from a file). */
export interface CageIssue {
  line: number;
  message: string;
}

/** Thrown for any unusable cage. `issues` lists every problem found, in line order. */
export class CageError extends Error {
  readonly issues: CageIssue[];
  constructor(issues: CageIssue[]) {
    const shown = issues.slice(0, 8).map(formatIssue).join('\n');
    const more = issues.length > 8 ? `\n... and ${issues.length - 8} more` : '';
    super(shown + more);
    this.name = 'CageError';
    this.issues = issues;
  }
}

export function formatIssue(i: CageIssue): string {
  return i.line > 0 ? `line ${i.line}: ${i.message}` : i.message;
}

/**
 * Thrown for a valid input that is larger than what a build or a device takes (a face with more
 * corners than a word holds, a vertex wider than a workgroup, a buffer over the device's binding
 * limit). The message says what and by how much, in the model's terms, for the user to act on.
 */
export class LimitError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'LimitError';
  }
}
