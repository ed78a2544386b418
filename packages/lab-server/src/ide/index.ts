export { addHomePage, homePage } from './home.js';
export { addIdePage, CSRF_META, WORKSPACE_META, withLabMeta } from './page.js';
export { EXERCISE_INFO, IDE_PAGE, rewriteIdePath } from './paths.js';
