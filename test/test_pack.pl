/*  Tests of the pack: the checkout installed with pack_install/2 into a
    fresh pack directory, then used from a directory that has nothing
    to do with the checkout, as a Prolog user would.

    SWI-Prolog 9.0.4's pack_install('file://Dir', ...) copies the whole
    directory Dir (copy_directory/2; it links only with link(true), as
    pack_install('.') does).  What a pack ships is what `git archive`
    gives (the `download` archive): .gitattributes leaves out test/,
    bench/ and .ci/.  So the tests install the directory that `git
    archive` of the working tree extracts to (every file git does not
    ignore, as it is now: added to a scratch index, written as a tree).  Without git, or outside a git checkout,
    they print a notice and are skipped.
*/

:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(library(filesex)).
:- use_module(library(lists)).
:- use_module(library(apply)).

:- dynamic
    tp_pack_install_dir/2.                 % TmpDir, PackDir

%   tp_pack_exportable: git can export the checkout.

tp_pack_exportable :-
    test_checkout_path('.', Checkout),
    (   catch(process_create(path(git), ['rev-parse', '--git-dir'],
                             [ cwd(Checkout), stdout(null), stderr(null),
                               process(Pid)
                             ]),
              _, fail),
        process_wait(Pid, exit(0))
    ->  true
    ;   format(user_error, "~NNotice: no git checkout: skipping the pack \c
                            installation tests~n", []),
        fail
    ).

%   tp_install_pack: export the checkout, install it into a fresh pack
%   directory (a child swipl, from an unrelated directory).

tp_install_pack :-
    tmp_file(oro_pack, Tmp),
    make_directory(Tmp),
    directory_file_path(Tmp, 'src/oro', Src),
    directory_file_path(Tmp, packs, Packs),
    directory_file_path(Tmp, elsewhere, Elsewhere),
    make_directory_path(Src),
    make_directory(Packs),
    make_directory(Elsewhere),
    asserta(tp_pack_install_dir(Tmp, Packs)),
    test_checkout_path('.', Checkout),
    directory_file_path(Tmp, index, Index),
    tp_run(sh, ['-c', 'export GIT_INDEX_FILE="$1" && git add -A && \c
                       git archive --worktree-attributes "$(git write-tree)" | \c
                       tar -x -C "$2"',
                sh, Index, Src],
           Checkout),
    uri_file_name(URL, Src),
    format(atom(Goal), "pack_install(~q, [package_directory(~q), interactive(false)])",
           [URL, Packs]),
    tp_run(swipl, ['-g', Goal, '-t', halt], Elsewhere).

tp_uninstall_pack :-
    forall(retract(tp_pack_install_dir(Tmp, _)),
           delete_directory_and_contents(Tmp)).

%   tp_run(+Exe, +Args, +Dir): run Exe in Dir (at most 60 s); it must exit 0.

tp_run(Exe, Args, Dir) :-
    process_create(path(timeout), ['60', Exe|Args],
                   [ cwd(Dir), stdout(pipe(Out)), stderr(pipe(Err)),
                     process(Pid)
                   ]),
    read_string(Out, _, _),
    read_string(Err, _, Errors),
    close(Out),
    close(Err),
    process_wait(Pid, Status),
    (   Status == exit(0)
    ->  true
    ;   format(user_error, "~w ~q: ~w~n~s~n", [Exe, Args, Status, Errors]),
        fail
    ).

tp_installed(Relative, Path) :-
    tp_pack_install_dir(_, Packs),
    atomic_list_concat([Packs, '/oro/', Relative], Path).

tp_elsewhere(Dir) :-
    tp_pack_install_dir(Tmp, _),
    directory_file_path(Tmp, elsewhere, Dir).

%   The output of a child swipl, one term per line.

tp_child_terms(Args, Dir, Terms) :-
    setup_call_cleanup(
        process_create(path(timeout), ['60', swipl|Args],
                       [ cwd(Dir), stdout(pipe(Out)), process(Pid) ]),
        ( read_string(Out, _, Text),
          process_wait(Pid, _)
        ),
        close(Out)),
    split_string(Text, "\n", "", Lines0),
    exclude(==(""), Lines0, Lines),
    maplist(tp_line_term, Lines, Terms).

tp_line_term(Line, Term) :-
    term_string(Term, Line).

tp_count_cups(Port, Reply) :-
    setup_call_cleanup(oro_connect(Port, Conn),
                       oro_call(Conn, countInstancesOf, ["Cup"], Reply),
                       oro_disconnect(Conn)).

:- begin_tests(pack_install, [ condition(tp_pack_exportable),
                               setup(tp_install_pack),
                               cleanup(tp_uninstall_pack)
                             ]).

test(ships_library_server_ontology_examples, true(Missing == [])) :-
    findall(F,
            ( member(F, [ 'pack.pl', 'README.md', 'prolog/oro.pl',
                          'prolog/oro_server.pl', 'prolog/oro/oro_store.pl',
                          'server/oro_server.pl', 'prolog/oro/server/oro_protocol.pl',
                          'prolog/oro/http/web/inspector.js',
                          'ontologies/commonsense.ttl',
                          'examples/plugins/count_instances.pl'
                        ]),
              tp_installed(F, Path),
              \+ exists_file(Path)
            ),
            Missing).
test(no_tests_nor_benchmarks, true(Shipped == [])) :-
    findall(D,
            ( member(D, [test, bench, '.ci', '.git']),
              tp_installed(D, Path),
              exists_directory(Path)
            ),
            Shipped).

%   The child answers library(File, Found) and server(File, Replies)
%   (test/fixtures/pack_user.pl): both libraries come from the pack.

test(library_and_embedded_server, true(Terms == Expected)) :-
    test_fixture('pack_user.pl', User),
    tp_pack_install_dir(_, Packs),
    tp_elsewhere(Dir),
    tp_child_terms([User, Packs], Dir, Terms),
    tp_installed('prolog/oro.pl', OroFile),
    tp_installed('prolog/oro_server.pl', ServerFile),
    atom_concat('http://kb.openrobots.org#', fork1, Fork),
    Expected = [ library(OroFile, [Fork]),
                 server(ServerFile, [ ["ok", "", "#end#"],
                                      ["ok", "[\"cup1\"]", "#end#"]
                                    ])
               ].
test(script_plugin_option_first, true(Reply = ok(_))) :-
    tp_installed('server/oro_server.pl', Script),
    tp_installed('examples/plugins/count_instances.pl', Plugin),
    atom_concat('--plugin=', Plugin, PluginOption),
    tp_elsewhere(Dir),
    test_server_process([Script, PluginOption, '--port=0'], Dir, Port,
                        tp_count_cups(Port, Reply), _).
test(library_main_plugin_option_first, true(Reply = ok(_))) :-
    tp_pack_install_dir(_, Packs),
    tp_installed('examples/plugins/count_instances.pl', Plugin),
    atom_concat('--plugin=', Plugin, PluginOption),
    format(atom(Attach), "attach_packs(~q, [])", [Packs]),
    tp_elsewhere(Dir),
    test_server_process([ '-g', Attach,
                          '-g', 'use_module(library(oro_server))',
                          '-g', oro_server_main,
                          '--', PluginOption, '--port=0'
                        ],
                        Dir, Port, tp_count_cups(Port, Reply), _).

:- end_tests(pack_install).
