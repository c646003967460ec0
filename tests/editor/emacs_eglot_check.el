;;; emacs_eglot_check.el --- editors/emacs/sphdeck.el with eglot against `sphdeck lsp' -*- lexical-binding: t -*-

;; A hand-run check of the Emacs set-up (not a ctest entry: Emacs is not a build dependency), the
;; same steps as the Neovim test: open tests/editor/bad_endcyc.k, wait for DK002 through Flymake,
;; hover ENDTIM, fix the line, wait for DK002 to go.  Exit 0 on success, 1 with a reason.
;;   SPHDECK=build/sphdeck emacs --batch -Q -l tests/editor/emacs_eglot_check.el
;; (Debian 12: apt-get install emacs-nox elpa-eglot.)

;;; Code:

(require 'package)
;; Debian's elpa-eglot on Emacs 28 (-Q skips the site start-up that lists it); built in on Emacs 29
(add-to-list 'package-directory-list "/usr/share/emacs/site-lisp/elpa")
(package-initialize)
(require 'eglot)
(require 'flymake)
(defvar sphdeck-check-root
  (expand-file-name "../.." (file-name-directory (or load-file-name buffer-file-name))))
(add-to-list 'load-path (expand-file-name "editors/emacs" sphdeck-check-root))
(require 'sphdeck)
(setq sphdeck-program (expand-file-name (or (getenv "SPHDECK") "build/sphdeck") sphdeck-check-root))
(setq make-backup-files nil create-lockfiles nil auto-save-default nil)

(defun sphdeck-check-fail (reason)
  (message "emacs-eglot: FAILED: %s" reason)
  (kill-emacs 1))

(defun sphdeck-check-wait (what condition &optional seconds)
  "Run the event loop until CONDITION holds, at most SECONDS (10); fail with WHAT."
  (let ((deadline (+ (float-time) (or seconds 10))))
    (while (and (not (funcall condition)) (< (float-time) deadline))
      (accept-process-output nil 0.05)
      (flymake-start))
    (unless (funcall condition) (sphdeck-check-fail (concat "timed out waiting for " what)))))

(defun sphdeck-check-dk002 ()
  (seq-find (lambda (d) (string-match-p "10000O" (flymake-diagnostic-text d)))
            (flymake-diagnostics)))

(find-file (expand-file-name "tests/editor/bad_endcyc.k" sphdeck-check-root))
(unless (eq major-mode 'lsdyna-mode)
  (sphdeck-check-fail (format "major mode %s, expected lsdyna-mode" major-mode)))
(message "emacs-eglot: Emacs %s, eglot %s, server %s" emacs-version
         (or (ignore-errors (package-version-join
                             (package-desc-version (cadr (assq 'eglot package-alist)))))
             "built in")
         sphdeck-program)
(apply #'eglot (eglot--guess-contact))  ; what eglot-ensure does after a command (none run in batch)
(sphdeck-check-wait "eglot to connect" (lambda () (eglot-current-server)))
(sphdeck-check-wait "the DK002 diagnostic" #'sphdeck-check-dk002)
(message "emacs-eglot: diagnostic: %s" (flymake-diagnostic-text (sphdeck-check-dk002)))

(let* ((hover (jsonrpc-request (eglot-current-server) :textDocument/hover
                               (list :textDocument (eglot--TextDocumentIdentifier)
                                     :position (list :line 5 :character 7))))
       (contents (plist-get hover :contents))
       (text (format "%s" (if (and (consp contents) (keywordp (car contents)))
                                (plist-get contents :value)
                              contents))))
  (unless (string-match-p "ENDTIM" (upcase text))
    (sphdeck-check-fail (format "hover on ENDTIM does not name it: %s" text)))
  (message "emacs-eglot: hover: %s" (replace-regexp-in-string "\n" " | " text)))

(goto-char (point-min))
(forward-line 5)
(delete-region (line-beginning-position) (line-end-position))
(insert "     0.002     10000")
(eglot--signal-textDocument/didChange)  ; batch Emacs runs no idle timers: send the change now
(sphdeck-check-wait "the DK002 diagnostic to go" (lambda () (not (sphdeck-check-dk002))))
(message "emacs-eglot: diagnostic gone after the edit")
(set-buffer-modified-p nil)
(eglot-shutdown (eglot-current-server))
(message "emacs-eglot: passed")
(kill-emacs 0)
;;; emacs_eglot_check.el ends here
