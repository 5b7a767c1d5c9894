window.handoutErrors = [];
window.addEventListener('error', function (e) { window.handoutErrors.push(String(e.message || e)); });
window.addEventListener('unhandledrejection', function (e) { window.handoutErrors.push(String(e.reason)); });
