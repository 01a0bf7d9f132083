/*  Run the whole test suite:

        swipl test/run_tests.pl

    Loads every test/test_*.pl, runs all units, prints a closing line
    `N passed, N failed` and exits 0 only if nothing failed.
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)),
   asserta(user:file_search_path(oro_test, Dir)).

:- use_module(library(plunit)).
:- use_module(library(apply)).

:- initialization(main, main).

:- dynamic summary/1.

:- multifile user:message_hook/3.

user:message_hook(plunit(Summary), silent, _) :-
    is_dict(Summary),
    retractall(summary(_)),
    assertz(summary(Summary)),
    fail.

main :-
    absolute_file_name(oro_test('.'), Dir, [file_type(directory)]),
    directory_files(Dir, Entries),
    include(test_file, Entries, Files0),
    msort(Files0, Files),
    forall(member(F, Files),
           ( directory_file_path(Dir, F, Path),
             load_files(Path, [if(not_loaded)])
           )),
    (   run_tests
    ->  true
    ;   true
    ),
    summary(S),
    Failed is S.failed + S.failed_assertions + S.sto,
    format("~d passed, ~d failed~n", [S.passed, Failed]),
    (   Failed =:= 0
    ->  halt(0)
    ;   halt(1)
    ).

test_file(F) :-
    sub_atom(F, 0, _, _, test_),
    file_name_extension(_, pl, F).
