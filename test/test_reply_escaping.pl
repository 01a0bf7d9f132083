:- module(test_reply_escaping, []).
:- use_module(library(plunit)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(random)).
:- use_module(library(memfile)).
:- use_module(library(oro/server/oro_protocol)).
:- use_module(oro_client_parsers).
:- use_module(oro_test_support).

/** <module> Tests: replies every real client reads back

The escaping of oro_encode_value/2 against re-implementations of the
two real clients' parsers (oro_client_parsers.pl): liboro's Boost
tokeniser and pyoro's eval().  Labels holding quotes, backslashes,
commas, brackets, TAB, CR, other control characters and non-BMP
characters go through the writer directly and over the socket
(getLabel, find, getDirectInstancesOf), and must read back in both.

The test client also checks every value line of every protocol test
(oro_test_client.pl), so the whole protocol test corpus and the replay
of the 2011 robot session go through both emulations.

Run: swipl test/run_tests.pl test_reply_escaping
*/

%   nasty_label(?Label): texts a label may hold.

nasty_label("say \"hi\"").
nasty_label("it's").
nasty_label("it's \"both\"").
nasty_label("back\\slash").
nasty_label("C:\\temp\\new").
nasty_label("ends with \\").
nasty_label("\\n is not a newline").
nasty_label("comma, inside").
nasty_label("[brackets]").
nasty_label("{braces}").
nasty_label("a]").
nasty_label("[").
nasty_label("tab\there").
nasty_label("cr\rhere").
nasty_label("crlf\r\nhere").
nasty_label("nl\nhere").
nasty_label("nul\u0000here").
nasty_label("bell\u0007 esc\u001b[0m del\u007f us\u001f ff\u000c vt\u000b").
nasty_label("non-BMP 😀 𝄞 日本").
nasty_label("line\u2028separator\u0085next").
nasty_label("#end#").
nasty_label("key:value").
nasty_label("\"quoted\"").
nasty_label("'single'").
nasty_label("true").
nasty_label("").

%   element_text(+Label, -Text): what both clients read for Label
%   inside a list or a map: a line break (CR LF, CR) is a newline and
%   NUL is U+FFFD (no escape can carry them to both).

element_text(Label, Text) :-
    split_string(Label, "", "", _),         % a string
    atomic_list_concat(Parts0, "\r\n", Label),
    atomic_list_concat(Parts0, "\n", T0),
    atomic_list_concat(Parts1, "\r", T0),
    atomic_list_concat(Parts1, "\n", T1),
    atomic_list_concat(Parts2, "\u0000", T1),
    atomic_list_concat(Parts2, "\uFFFD", T2),
    atom_string(T2, Text).

%   verbatim(+Label): a plain string reply holds Label as is.

verbatim(Label) :-
    split_string(Label, "\n\r\u0000", "", [_]),
    \+ ( sub_string(Label, _, _, _, "\""),
         sub_string(Label, _, _, _, "'")
       ).

%   one_value_line(+Line): no line break, not the terminator.

one_value_line(Line) :-
    split_string(Line, "\n\r", "", [_]),
    Line \== "#end#".

%   read_plain_string(+Label, +Line): both clients read the plain
%   string reply Line of Label as documented in oro_encode_value/2.

read_plain_string(Label, Line) :-
    one_value_line(Line),
    \+ reply_line_problem(ok, Line, _),
    liboro_clean(Line, LiboroText),
    pyoro_read_line(Line, Pyoro),
    (   verbatim(Label)
    ->  LiboroText == Label,                % as from oro-server 0.8.2
        (   sub_string(Label, _, _, _, "\\")
        ->  true                            % pyoro reads escapes
        ;   Pyoro == value(str(Label))
        )
    ;   Pyoro == value(str(Label))          % escaped: Python wins
    ).

%   read_list(+Labels, +Line): both clients read the list Line of
%   Labels back.

read_list(Labels, Line) :-
    one_value_line(Line),
    \+ reply_line_problem(ok, Line, _),
    maplist(element_text, Labels, Texts),
    maplist(str, Texts, Strs),
    pyoro_read_line(Line, value(list(Strs))),
    maplist(liboro_clean, Texts, Cleaned),
    sort(Cleaned, Set),
    liboro_read_line(Line, value(set(Set))).

str(Text, str(Text)).

:- begin_tests(reply_escaping_writer).

test(list_elements, Bad == []) :-
    findall(Label,
            ( nasty_label(Label),
              oro_encode_value(list([Label, string(Label)]), Line),
              \+ read_list([Label, Label], Line)
            ),
            Bad).
test(all_labels_in_one_list, true) :-
    findall(Label, nasty_label(Label), Labels),
    oro_encode_value(list(Labels), Line),
    read_list(Labels, Line).
test(map_elements, Bad == []) :-
    findall(Label,
            ( nasty_label(Label),
              oro_encode_value(map([Label-Label, id-Label]), Line),
              element_text(Label, Text),
              \+ ( one_value_line(Line),
                   \+ reply_line_problem(ok, Line, _),
                   pyoro_read_line(Line, value(dict(Pairs))),
                   msort(Pairs, Sorted),
                   msort([str(Text)-str(Text), str("id")-str(Text)], Sorted),
                   liboro_read_line(Line, value(map(Map))),
                   liboro_clean(Text, Clean),
                   memberchk("id"-Clean, Map)
                 )
            ),
            Bad).
test(map_key_without_colon, true(Map == ["tab\tkey"-"a,b\"c"])) :-
    oro_encode_value(map(["tab\tkey"-"a,b\"c"]), Line),
    liboro_read_line(Line, value(map(Map))).
test(lookup_pairs, Bad == []) :-     % liboro reads a list of pairs as a map
    findall(Label,
            ( nasty_label(Label),
              oro_encode_value(list([list([Label, "INSTANCE"]),
                                     list([x, Label])]), Line),
              element_text(Label, Text),
              liboro_clean(Text, Clean),
              \+ ( \+ reply_line_problem(ok, Line, _),
                   pyoro_read_line(Line, value(list([list([str(Text), str("INSTANCE")]),
                                                     list([str("x"), str(Text)])]))),
                   liboro_read_line(Line, value(map(Map))),
                   (   Clean == "x"
                   ->  true
                   ;   memberchk(Clean-"INSTANCE", Map)
                   ),
                   memberchk("x"-Clean, Map)
                 )
            ),
            Bad).
test(plain_strings, Bad == []) :-
    findall(Label,
            ( nasty_label(Label),
              oro_encode_value(string(Label), Line),
              \+ read_plain_string(Label, Line)
            ),
            Bad).
test(plain_string_never_eval_code, true(Pyoro == value(str(Label)))) :-
    Label = "\" + str(__import__('os').getpid()) + \"",
    oro_encode_value(string(Label), Line),
    pyoro_read_line(Line, Pyoro).
test(event_content, Bad == []) :-
    findall(Label,
            ( nasty_label(Label),
              event_lines(Label, Lines),
              \+ ( Lines = ["event", "w1", Content, "#end#"],
                   \+ reply_line_problem(event, Content, _),
                   element_text(Label, Text),
                   pyoro_read_line(Content, value(list([str(Text)])))
                 )
            ),
            Bad).
test(raw_one_line, Line == "{\"a\": 1, \"b\":  2 }") :-
    oro_encode_value(raw("{\"a\":\n1, \"b\":\r\n 2\r}"), Line).
test(random_texts, Bad == []) :-
    set_random(seed(35)),
    numlist(1, 1500, Is),
    findall(Text,
            ( member(_, Is),
              random_text(Text),
              oro_encode_value(list([Text]), Line),
              \+ read_list([Text], Line)
            ),
            Bad).

:- end_tests(reply_escaping_writer).

event_lines(Label, Lines) :-
    setup_call_cleanup(
        new_memory_file(MF),
        ( setup_call_cleanup(
              open_memory_file(MF, write, Out, [encoding(utf8)]),
              oro_write_event(Out, w1, list([Label])),
              close(Out)),
          memory_file_to_string(MF, Text, utf8)
        ),
        free_memory_file(MF)),
    split_string(Text, "\n", "", Lines0),
    append(Lines, [""], Lines0).

random_text(Text) :-
    random_between(0, 12, Length),
    length(Codes, Length),
    maplist(random_code, Codes),
    string_codes(Text, Codes).

random_code(Code) :-
    random_member(Code, [0'a, 0' , 0'", 0'', 0'\\, 0',, 0':, 0'[, 0'], 0'{,
                         0'}, 0'n, 0'u, 0'#, 9, 10, 13, 0, 1, 27, 127,
                         0x85, 0x2028, 0xE9, 0x1F600]).


                 /*******************************
                 *          OVER THE SOCKET     *
                 *******************************/

%   oro_literal(+Label, -Literal): Label as a quoted literal of a
%   statement, one line: `#` and control characters are written
%   \uXXXX (`#end#` anywhere would end the request), a backslash `\\\\`
%   (the list and then the statement are Java-unescaped).

oro_literal(Label, Literal) :-
    string_codes(Label, Codes),
    foldl(literal_code, Codes, Parts, []),
    atomics_to_string(["\""|Parts], Body),
    string_concat(Body, "\"", Literal).

literal_code(0'", ["\\\""|T], T) :- !.
literal_code(0'\\, ["\\\\\\\\"|T], T) :- !.
literal_code(C, [Part|T], T) :-
    (   C < 32
    ;   C =:= 127
    ;   C == 0'#                            % `#end#` would end the request
    ),
    !,
    format(string(Part), "\\u~|~`0t~16r~4+", [C]).
literal_code(C, [Char|T], T) :-
    char_code(Char, C).

%   labelled(?N, ?Label, ?Id): the labels added over the socket.

labelled(N, Label, Id) :-
    findall(L, nasty_label(L), Labels),
    nth1(N, Labels, Label),
    format(atom(Id), "esc_~w", [N]).

%   add_labels: one add per label (the request's list splitter reads a
%   `'` as a quote too, so labels are not mixed in one list).

add_labels :-
    test_ok(add, ["[EscCup rdfs:subClassOf owl:Thing]"]),
    forall(labelled(_, Label, Id),
           ( oro_literal(Label, Literal),
             format(string(Request), "[~w rdf:type EscCup, ~w rdfs:label ~w]",
                    [Id, Id, Literal]),
             test_ok(add, [Request])
           )).

:- begin_tests(reply_escaping_socket,
               [ setup((test_server_start_testsuite, add_labels)),
                 cleanup(test_server_stop)
               ]).

test(get_label, Bad == []) :-
    findall(Label,
            ( labelled(_, Label, Id),
              Label \== "",                 % getLabel gives the id
              test_ok(getLabel, [Id], Line),
              \+ read_plain_string(Label, Line)
            ),
            Bad).
test(find_label, Bad == []) :-
    findall(Label,
            ( labelled(_, Label, Id),
              format(string(Pattern), "[~w rdfs:label ?l]", [Id]),
              test_ok(find, [l, Pattern], Line),
              \+ read_list([Label], Line)
            ),
            Bad).
test(resource_details, Bad == []) :-  % JSON, but liboro tokenises it
    findall(Label,
            ( labelled(_, Label, Id),
              Label \== "",
              test_ok(getResourceDetails, [Id], Line),
              element_text(Label, Text),
              \+ ( \+ reply_line_problem(ok, Line, _),
                   liboro_read_line(Line, value(map(_))),
                   pyoro_read_line(Line, value(dict(Pairs))),
                   memberchk(str("name")-str(Text), Pairs)
                 )
            ),
            Bad).
test(direct_instances, true(Got == Expected)) :-
    test_ok(getDirectInstancesOf, ['EscCup'], Line),
    \+ reply_line_problem(ok, Line, _),
    pyoro_read_line(Line, value(dict(Pairs))),
    msort(Pairs, Got),
    findall(str(IdS)-str(Text),
            ( labelled(_, Label, Id),
              atom_string(Id, IdS),
              element_text(Label, Text)
            ),
            Expected0),
    msort(Expected0, Expected).
test(direct_instances_liboro, true(Got == Expected)) :-
    test_ok(getDirectInstancesOf, ['EscCup'], Line),
    liboro_read_line(Line, value(map(Got))),
    findall(IdS-Clean,
            ( labelled(_, Label, Id),
              atom_string(Id, IdS),
              element_text(Label, Text),
              liboro_clean(Text, Clean)
            ),
            Expected0),
    keysort(Expected0, Expected).

:- end_tests(reply_escaping_socket).


                 /*******************************
                 *   THE EMULATIONS THEMSELVES  *
                 *******************************/

%   Known behaviours of Boost's escaped_list_separator, liboro and
%   Python 3.11 (checked against the real ones).

:- begin_tests(client_parsers).

test(boost_plain, T == ["a", "b"]) :-
    liboro_tokens("a,b", T).
test(boost_quoted_comma, T == ["a,b", "c"]) :-
    liboro_tokens("\"a,b\",c", T).
test(boost_escapes, T == ["a,b\"c\\d\ne"]) :-
    liboro_tokens("a\\,b\\\"c\\\\d\\ne", T).
test(boost_empty, T == []) :-
    liboro_tokens("", T).
test(boost_trailing_separator, T == ["a", ""]) :-
    liboro_tokens("a,", T).
test(boost_unknown_escape,
     throws(liboro(crash(escaped_list_error(unknown_escape(t)))))) :-
    liboro_tokens("\"a\\tb\"", _).
test(boost_unicode_escape,
     throws(liboro(crash(escaped_list_error(unknown_escape(u)))))) :-
    liboro_tokens("\"a\\u0008\"", _).
test(boost_final_escape,
     throws(liboro(crash(escaped_list_error(cannot_end_with_escape))))) :-
    liboro_tokens("a\\", _).
test(clean_value, C == "x y") :-
    liboro_clean(" \t\"x y\" ", C).
test(clean_value_single, C == "x") :-
    liboro_clean("'x'", C).
test(clean_value_one_quote, C == "") :-
    liboro_clean("\"", C).
test(clean_value_mixed, C == "'x\"") :-
    liboro_clean("'x\"", C).
test(liboro_plain_string, R == value(string("say \\\"hi\\\""))) :-
    liboro_read_line("\"say \\\"hi\\\"\"", R).
test(liboro_number, R == value(int(42))) :-
    liboro_read_line("42", R).
test(liboro_bool, R == value(bool(false))) :-
    liboro_read_line("false", R).
test(liboro_pairs, R == value(map(["a"-"b", "c"-"d"]))) :-
    liboro_read_line("[[\"a\",\"b\"],[\"c\",\"d\"]]", R).
test(liboro_map_key_colon, R == value(map(["k"-"x:v"]))) :-
    liboro_read_line("{\"k:x\":\"v\"}", R).
test(liboro_tab_escape_aborts,
     R == crash(escaped_list_error(unknown_escape(t)))) :-
    liboro_read_line("{\"tab1\":\"a\\tb\"}", R).
test(liboro_nul, R == crash(nul_in_line)) :-
    liboro_read_line("[\"a\u0000\"]", R).
test(python_escapes, R == value(str("\tAé😀A\\q\u0000"))) :-
    python_literal("\"\\t\\x41\\u00e9\\U0001F600\\101\\q\\0\"", R).
test(python_concatenation, R == value(str("ab"))) :-
    python_literal("'a' \"b\"", R).
test(python_unterminated, R == error(syntax)) :-
    python_literal("\"a\\\"", R).
test(python_values,
     R == value(list([num("1", 1), num("-2500.0", -2500.0), bool(true),
                      none]))) :-
    python_literal("[1, -2.5e3, True, None,]", R).
test(python_dict_last_wins, R == value(dict([str("a")-num("2", 2)]))) :-
    python_literal("{\"a\": 1, \"a\": 2}", R).
test(python_name, R == error(name)) :-
    python_literal("[null]", R).
test(python_nul, R == crash(nul_in_source)) :-
    python_literal("\"a\u0000\"", R).
test(python_triple_quote, R == unsupported(triple_quoted_string)) :-
    python_literal("\"\"\"x\"\"\"", R).
test(python_uuid, R == error(syntax)) :-
    python_literal("0b0c238b-290b-4886-92ff-d3a34833a391", R).
test(pyoro_true, R == value(bool(true))) :-
    pyoro_read_line("TRUE", R).
test(pyoro_empty, R == skipped) :-
    pyoro_read_line("", R).
test(pyoro_raw, R == raw("a b")) :-
    pyoro_read_line("a b", R).

%   The check of the test client catches what the clients fail on.

test(check_tab_escape, P = liboro_aborts(_)) :-
    reply_line_problem(ok, "[\"a\\tb\"]", P).
test(check_raw_cr, P == raw_line_break) :-
    reply_line_problem(ok, "[\"a\rb\"]", P).
test(check_unescaped_quote, P == pyoro_cannot_eval) :-
    reply_line_problem(ok, "[\"a\"x\"]", P).
test(check_disagreement, P = clients_disagree(_, _)) :-
    reply_line_problem(ok, "[\"a\" \"b\"]", P).
test(check_nul, P = liboro_aborts(_)) :-
    reply_line_problem(event, "[\"a\u0000\"]", P).
test(check_good, fail) :-
    reply_line_problem(ok, "[\"a\tb\",\"c\\\\d\\\"\"]", _).

:- end_tests(client_parsers).
