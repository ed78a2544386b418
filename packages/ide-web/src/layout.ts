/** Draggable sashes between explorer, editor, diagram and the bottom panel. */
const root = document.documentElement;
for (const sash of document.querySelectorAll<HTMLElement>('.sash')) {
    sash.addEventListener('pointerdown', (down) => {
        down.preventDefault();
        sash.setPointerCapture(down.pointerId);
        const which = sash.dataset.resize;
        const move = (e: PointerEvent): void => {
            if (which === 'explorer') root.style.setProperty('--explorer-width', `${Math.max(120, e.clientX)}px`);
            else if (which === 'diagram') root.style.setProperty('--diagram-width', `${Math.max(200, window.innerWidth - e.clientX)}px`);
            else if (which === 'panel') root.style.setProperty('--panel-height', `${Math.max(80, window.innerHeight - e.clientY - 22)}px`);
        };
        const up = (): void => {
            sash.removeEventListener('pointermove', move);
            sash.removeEventListener('pointerup', up);
        };
        sash.addEventListener('pointermove', move);
        sash.addEventListener('pointerup', up);
    });
}
export {};
