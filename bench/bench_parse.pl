/*  oro benchmark: the request path without the store -- reading a
    request, decoding its parameters, parsing statements, expanding and
    contracting names, encoding the reply -- each fast path next to the
    general path it stands for.

        swipl bench/bench_parse.pl [--samples=5]

    Times are thread CPU time, the best of Samples runs of many
    iterations, so that other jobs on the machine disturb them little.
    The general paths are internal predicates of the oro_parse_* modules
    and of oro_protocol, called module-qualified; they give the same results
    (test/test_parse.pl checks it).
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(oro/oro_names)).
:- use_module(library(memfile)).
:- use_module(library(option)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(main), [argv_options/3]).
:- use_module(library(oro/server/oro_protocol)).
:- use_module(bench_common).

:- initialization(main, main).

opt_type(samples, samples, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(samples(Samples), Options, 5),
    nb_setval(bench_samples, Samples),
    bench_machine,
    nl,
    format("~w~t~50|~w~t~14+~w~t~14+~w~n",
           [operation, 'fast path', general, 'speed-up']),
    statements(Statements),
    forall(member(Kind-Text, Statements),
           ( format(atom(Name), 'statement, ~w', [Kind]),
             row(Name, 5000, oro_parse_statement:parse_statement(Text, _),
                 oro_parse_statement:general_statement(Text, _))
           )),
    batch(100, Batch),
    set_text(Batch, SetText),
    sub_string(SetText, 1, _, 1, Inner),
    row('set of 100 statements, per element', 200,
        oro_parse_collection(set, SetText, _),
        code_by_code_elements(Inner), 100),
    forall(quoted_set(Kind, Batch, QuotedText),
           ( format(atom(Name), 'set of 100, ~w, per element', [Kind]),
             sub_string(QuotedText, 1, _, 1, QuotedInner),
             row(Name, 200,
                 oro_parse_collection(set, QuotedText, _),
                 code_by_code_elements(QuotedInner), 100)
           )),
    row('oro_statements/3, 100, per statement', 200,
        oro_statements(Batch, _, _), -, 100),
    row('clean value', 20000,
        oro_clean_value(" kitchen_table ", _),
        oro_parse_lexer:general_clean_value(" kitchen_table ", _)),
    row('name, plain', 20000, oro_name_iri("furniture1", _), -),
    row('name, prefixed', 20000, oro_name_iri("rdf:type", _), -),
    row('name, <IRI>', 20000, oro_name_iri("<http://x.org/a#b>", _), -),
    rdf_iri('http://kb.openrobots.org#furniture1', Default),
    rdf_iri('http://www.w3.org/2002/07/owl#Thing', Thing),
    row('contraction, default namespace', 50000,
        oro_iri_name(Default, _), -),
    row('contraction, owl:', 20000, oro_iri_name(Thing, _), -),
    answers(500, Answers),
    row('encode a list of 500 strings, per element', 100,
        oro_encode_value(list(Answers), _),
        oro_protocol:elements(Answers, _, []), 500),
    labels(500, Labels),
    row('encode 500 escaped labels, per element', 100,
        oro_encode_value(list(Labels), _), -, 500),
    row('encode a plain string reply', 20000,
        oro_encode_value(string("baboon monkey"), _), -),
    row('encode a string reply with quotes', 20000,
        oro_encode_value(string("say \"hi\""), _), -),
    requests(Requests),
    forall(member(Kind-Request-N, Requests),
           ( format(atom(Name), 'read a request, ~w', [Kind]),
             row(Name, 1, read_requests(Request, N), -, N)
           )).

rdf_iri(IRI, IRI).

		 /*******************************
		 *            INPUTS            *
		 *******************************/

statements([ 'local names'         - "obj12 isOn furniture3",
             'boolean object'      - "obj12 isVisible true",
             'prefixed predicate'  - "obj12 rdf:type Cup",
             'integer object'      - "obj12 weight 150",
             'quoted string'       - "obj12 rdfs:label \"a cup\"",
             'typed literal'       - "obj12 weight \"150\"^^xsd:int",
             'variables'           - "?o isAt ?f"
           ]).

batch(N, Statements) :-
    numlist(1, N, Is),
    maplist([I, S]>>( F is I mod 50,
                      format(string(S), "obj~d isOn furniture~d", [I, F])
                    ), Is, Statements).

set_text(Statements, Text) :-
    atomic_list_concat(Statements, ', ', Inner),
    atomics_to_string(["[", Inner, "]"], Text).

%   quoted_set(-Kind, +Statements, -Text): Statements as a set the way
%   the clients send it (ORO-SPEC 2.4): liboro double-quotes each
%   element, escaping its inner quotes, pyoro writes Python's repr.
%   One statement in 20 then gives a label, a quoted literal.

quoted_set('liboro, "a b c"', Statements, Text) :-
    quoted_elements(Statements, "\"", ",", Text).
quoted_set('liboro, with labels', Statements0, Text) :-
    labelled(Statements0, Statements),
    quoted_elements(Statements, "\"", ",", Text).
quoted_set('pyoro, \'a b c\'', Statements, Text) :-
    quoted_elements(Statements, "'", ", ", Text).
quoted_set('pyoro, with labels', Statements0, Text) :-
    labelled(Statements0, Statements),
    quoted_elements(Statements, "'", ", ", Text).

labelled(Statements0, Statements) :-
    findall(S,
            ( nth1(I, Statements0, S0),
              (   I mod 20 =:= 0
              ->  format(string(S), "obj~d rdfs:label \"cup ~d\"", [I, I])
              ;   S = S0
              )
            ),
            Statements).

quoted_elements(Statements, Quote, Separator, Text) :-
    quoted(Quote, Statements, Elements),
    atomic_list_concat(Elements, Separator, Inner),
    atomics_to_string(["[", Inner, "]"], Text).

quoted("\"", Statements, Elements) :-
    bench_quoted(Statements, Elements).
quoted("'", Statements, Elements) :-
    maplist([S, E]>>atomics_to_string(["'", S, "'"], E), Statements,
            Elements).

%   code_by_code_elements(+Inner): the inside of a collection decoded
%   the general way, code by code: what the fast paths stand for.

code_by_code_elements(Inner) :-
    oro_parse_lexer:general_tokenize(Inner, 0',, Tokens),
    maplist(oro_parse_lexer:general_clean_value, Tokens, _).

answers(N, Answers) :-
    numlist(1, N, Is),
    maplist([I, string(A)]>>format(atom(A), "obj~d", [I]), Is, Answers).

labels(N, Labels) :-
    numlist(1, N, Is),
    maplist([I, L]>>format(string(L), "cup\t~d \"blue\"", [I]), Is, Labels).

%   Requests as the bytes a client sends, and how many of them each
%   input holds.

requests([ hello        - Hello - 1000,
           'add 1'      - Add1  - 1000,
           'add 100'    - Add   - 100
         ]) :-
    repeated(1000, "hello\n#end#\n", Hello),
    repeated(1000, "add\n[obj1 isOn furniture1]\n#end#\n", Add1),
    batch(100, Batch),
    set_text(Batch, Set),
    atomics_to_string(["add\n", Set, "\n#end#\n"], One),
    repeated(100, One, Add).

repeated(N, Text, All) :-
    length(Texts, N),
    maplist(=(Text), Texts),
    atomics_to_string(Texts, All).

%   read_requests(+Text, +N): read the N requests of Text from an octet
%   stream, as a socket is read.

read_requests(Text, N) :-
    setup_call_cleanup(
        new_memory_file(MF),
        ( setup_call_cleanup(
              open_memory_file(MF, write, Out, [encoding(utf8)]),
              write(Out, Text),
              close(Out)),
          setup_call_cleanup(
              open_memory_file(MF, read, In, [encoding(octet)]),
              ( oro_reader(In, Reader, []),
                read_n(N, Reader)
              ),
              close(In))
        ),
        free_memory_file(MF)).

read_n(N, Reader0) :-
    (   N =:= 0
    ->  true
    ;   oro_read_request(Reader0, request(_, _), Reader),
        N1 is N - 1,
        read_n(N1, Reader)
    ).

		 /*******************************
		 *            TIMING            *
		 *******************************/

%   row(+Name, +Iterations, :Fast, :General)
%   row(+Name, +Iterations, :Fast, :General, +PerCall)
%
%   Print the time of one call of Fast and of General (`-`: none),
%   divided by PerCall, in microseconds.

row(Name, Iterations, Fast, General) :-
    row(Name, Iterations, Fast, General, 1).

row(Name, Iterations, Fast, General, PerCall) :-
    cpu_time(Fast, Iterations, PerCall, F),
    (   General == (-)
    ->  G = (-),
        Ratio = ""
    ;   cpu_time(General, Iterations, PerCall, G),
        format(string(Ratio), "~1fx", [G / max(F, 0.001)])
    ),
    bench_micros(F, FText),
    bench_micros(G, GText),
    format("~w~t~50|~w~t~14+~w~t~14+~w~n", [Name, FText, GText, Ratio]),
    flush_output.

%   cpu_time(:Goal, +Iterations, +PerCall, -Micros): the best over the
%   samples of the thread CPU time of Iterations calls of Goal, per call
%   and divided by PerCall.

cpu_time(Goal, Iterations, PerCall, Micros) :-
    nb_getval(bench_samples, Samples),
    findall(T,
            ( between(1, Samples, _),
              statistics(cputime, T0),
              \+ \+ forall(between(1, Iterations, _), Goal),
              statistics(cputime, T1),
              T is (T1 - T0) * 1.0e6 / Iterations / PerCall
            ),
            Ts),
    min_list(Ts, Micros).
