/** Text and attribute values in the lab's HTML: `&`, quotes and angle brackets escaped. */
export function escapeHtml(s: string): string {
    return s.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/'/g, '&#39;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}
