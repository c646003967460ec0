;;; sphdeck.el --- LS-DYNA and OpenRadioss decks with the sphdeck language server -*- lexical-binding: t -*-

;; Two major modes, `lsdyna-mode' and `openradioss-mode' (comments, keyword lines highlighted), the
;; files they open, and `sphdeck lsp' registered with eglot (built into Emacs 29; Debian 12's Emacs
;; 28 gets it from the package elpa-eglot).  In an init file:
;;   (add-to-list 'load-path "/path/to/sphdeck/editors/emacs")
;;   (require 'sphdeck)
;;   (setq sphdeck-program "/path/to/sphdeck")          ; when sphdeck is not on PATH
;;   (add-hook 'lsdyna-mode-hook #'eglot-ensure)
;;   (add-hook 'openradioss-mode-hook #'eglot-ensure)

;;; Code:

(defgroup sphdeck nil
  "LS-DYNA and OpenRadioss input decks checked by sphdeck."
  :group 'languages)

(defcustom sphdeck-program "sphdeck"
  "The sphdeck executable; eglot runs it as `sphdeck lsp'."
  :type 'string)

(defvar lsdyna-mode-font-lock-keywords
  '(("^\\*[A-Za-z_0-9+-]+" . font-lock-keyword-face)
    ("&[A-Za-z_][A-Za-z_0-9]*" . font-lock-variable-name-face))
  "Keyword lines (*NAME) and &name parameters.")

(defvar openradioss-mode-font-lock-keywords
  '(("^/[A-Z_0-9/]+" . font-lock-keyword-face)
    ("^#include\\b.*" . font-lock-preprocessor-face))
  "Keyword lines (/NAME/...) and #include lines.")

;;;###autoload
(define-derived-mode lsdyna-mode prog-mode "LS-DYNA"
  "Major mode for LS-DYNA keyword decks: `$' comments, keywords highlighted."
  (setq-local comment-start "$")
  (setq-local comment-start-skip "^\\$+ *")
  (setq-local font-lock-defaults '(lsdyna-mode-font-lock-keywords t))
  (setq-local indent-tabs-mode nil))

;;;###autoload
(define-derived-mode openradioss-mode prog-mode "OpenRadioss"
  "Major mode for OpenRadioss starter decks: `#' comments, keywords highlighted."
  (setq-local comment-start "#")
  (setq-local comment-start-skip "^#+ *")
  (setq-local font-lock-defaults '(openradioss-mode-font-lock-keywords t))
  (setq-local indent-tabs-mode nil))

(defun sphdeck-dialect-of-buffer ()
  "The dialect of the current buffer from its first keyword line, or nil.
LS-DYNA keywords start with `*', OpenRadioss ones with `/' or a
`#RADIOSS' header."
  (save-excursion
    (goto-char (point-min))
    (when (re-search-forward "^\\(#RADIOSS\\|/[A-Z]\\|\\*[A-Za-z]\\)" (+ (point) 20000) t)
      (if (eq (char-after (match-beginning 0)) ?*) 'lsdyna 'openradioss))))

;;;###autoload
(defun sphdeck-include-mode ()
  "Major mode for a .inc file: the dialect its content shows.
Falls back to `fundamental-mode'."
  (interactive)
  (pcase (sphdeck-dialect-of-buffer)
    ('lsdyna (lsdyna-mode))
    ('openradioss (openradioss-mode))
    (_ (fundamental-mode))))

;;;###autoload
(progn
  (add-to-list 'auto-mode-alist '("\\.\\(k\\|key\\|dyn\\)\\'" . lsdyna-mode))
  (add-to-list 'auto-mode-alist '("\\.rad\\'" . openradioss-mode))
  (add-to-list 'auto-mode-alist '("\\.inc\\'" . sphdeck-include-mode)))

(defvar eglot-server-programs)
(with-eval-after-load 'eglot
  (add-to-list 'eglot-server-programs
               `((lsdyna-mode openradioss-mode) . ,(lambda (&rest _) (list sphdeck-program "lsp")))))

(provide 'sphdeck)
;;; sphdeck.el ends here
