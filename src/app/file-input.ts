/** The page's ways in for files: the open-file dialog and dropping a file on the window. */

/** Ask the user for a file of the kinds `accept` names, and hand it to `open`. */
export function openFile(open: (file: File) => void, accept = '.obj,text/plain'): void {
  const input = document.createElement('input');
  input.type = 'file';
  input.accept = accept;
  input.addEventListener('change', () => {
    const file = input.files?.[0];
    if (file) open(file);
  });
  input.click();
}

/** Files dropped on the window go to `open`; the page's drop target shows while one is dragged over. */
export function enableDrop(open: (file: File) => void): void {
  const overlay = document.getElementById('drop-target')!;
  let depth = 0;
  const hasFiles = (e: DragEvent) => [...(e.dataTransfer?.types ?? [])].includes('Files');
  window.addEventListener('dragenter', (e) => {
    if (!hasFiles(e)) return;
    depth++;
    overlay.hidden = false;
  });
  window.addEventListener('dragleave', () => {
    depth = Math.max(0, depth - 1);
    if (depth === 0) overlay.hidden = true;
  });
  window.addEventListener('dragover', (e) => {
    if (hasFiles(e)) e.preventDefault();
  });
  window.addEventListener('drop', (e) => {
    e.preventDefault();
    depth = 0;
    overlay.hidden = true;
    const file = e.dataTransfer?.files?.[0];
    if (file) open(file);
  });
}
