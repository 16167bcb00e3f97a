/** diagrams/embed.html: a sample blog post with one figure in an iframe and one custom element. */
import './page.css';
import '../element.ts';
